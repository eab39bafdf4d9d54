// SPDX-License-Identifier: BSD-2-Clause
// The suppression chain, from a frame's candidates to its detections: greedy NMS (the
// toolbox's), then for the calibrated method box voting and the thesis's score-ratio
// step (3.3). Static-scene rejection follows it in the detector, after the calibrated
// search has seen the detections (suppress/static_scene.h).
#pragma once

#include <calped/detector.h>
#include <calped/model.h>
#include <calped/status.h>

#include <vector>

namespace calped {

class Suppression
{
public:
	// nms false keeps every candidate (boxVoting and scoreRatio then make no sense, and
	// DetectorConfig::validate() refuses them). Scratch for `capacity` candidates.
	Status init(const ModelParams &params, bool nms, bool boxVoting, bool scoreRatio,
		    int capacity);

	// Suppresses in place: the detections kept, best first, are boxes[0 .. returned).
	int run(Detection *boxes, int count);

private:
	float overlap_ = 0.65f;
	bool useUnion_ = false;
	bool boxVoting_ = false, scoreRatio_ = false;
	std::vector<Detection> sorted_;
	std::vector<int> order_;
};

} // namespace calped
