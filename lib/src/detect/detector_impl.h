// SPDX-License-Identifier: BSD-2-Clause
// What calped::Detector runs: the stages in the order a frame flows through them (input,
// pyramid, search, classification, suppression, world coordinates), set up once in init().
#pragma once

#include <calped/calibration.h>
#include <calped/detector.h>

#include "classify/candidates.h"
#include "classify/classifier.h"
#include "core/thread_pool.h"
#include "input/input_stage.h"
#include "pyramid/pyramid.h"
#include "search/calibrated_search.h"
#include "search/window_boxes.h"
#include "suppress/static_scene.h"
#include "suppress/suppression.h"

namespace calped {

class DetectorImpl
{
public:
	Status init(const Model &model, const DetectorConfig &config);
	Status detect(const ImageView &image, Detections &out);

	DetectorConfig config; // as validated, method resolved
	FrameStats stats;
	Pyramid pyramid;
	Classifier classifier;
	CalibratedSearch calibratedSearch; // the calibrated method only

private:
	Status checkImage(const ImageView &image) const;

	ThreadPool pool_; // DetectorConfig::threads: the stages split their work over it
	bool calibrated_ = false;
	bool hasCamera_ = false;
	CameraModel camera_;
	InputStage input_;
	Candidates candidates_;
	Suppression suppression_;
	bool rejectStatic_ = false;
	StaticScene static_;
};

} // namespace calped
