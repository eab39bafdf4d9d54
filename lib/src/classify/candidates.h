// SPDX-License-Identifier: BSD-2-Clause
// The windows of one frame that passed the cascade, as boxes in input-image pixels: what
// the search stage's classification yields and the suppression stage takes. Capacity
// fixed at setup; what does not fit is counted, never silently lost.
#pragma once

#include <calped/detector.h>
#include <calped/status.h>

#include <cstdint>
#include <vector>

#include "classify/classifier.h"
#include "pyramid/pyramid.h"
#include "search/window_boxes.h"

namespace calped {

class Candidates
{
public:
	Status init(int capacity, const WindowBoxes &boxes);
	void clear() { count_ = 0; }

	// Classifies every window of a level (`listed` null) or only the listed ones (row <<
	// 16 | column), keeps the hits as boxes and counts windows, candidates and drops.
	void classify(const Classifier &classifier, const PyramidLevel &level,
		      const LevelChannels &channels, const uint32_t *listed, size_t count,
		      FrameStats &stats);

	Detection *data() { return boxes_.data(); }
	int count() const { return count_; }
	int capacity() const { return int(boxes_.size()); }

private:
	WindowBoxes map_;
	std::vector<kernels::WindowHit> hits_;
	std::vector<Detection> boxes_;
	int count_ = 0;
};

} // namespace calped
