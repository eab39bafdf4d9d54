// SPDX-License-Identifier: BSD-2-Clause
// Synthetic head/foot observations of people walking on the ground in front of a known
// camera (tests/selfcal and bench/selfcal_synthetic.cpp).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <calped/self_calibration.h>

namespace calped::selfcal_test {

struct SceneConfig {
	double focal = 1000, tilt = 0.35, roll = 0, height = 6; // pixels, radians, metres
	int width = 1280, height_px = 720;
	int people = 300;
	double personHeight = 1.7, personHeightSd = 0.08; // metres
	double pixelNoise = 2;      // sd of the head and foot rows and the foot column, pixels
	double outlierFraction = 0; // sitting, cut off, merged, false positives in equal shares
	double minBoxHeight = 24;   // boxes smaller than this are not detected
	uint32_t seed = 1;
	// Straight down (tilt ~ 90 degrees): the box spans the head and foot rows whichever is
	// lower, as a detector's axis-aligned box would.
	bool boxesSpanHeadAndFoot = false;
};

// The scene's camera (principal point at the image centre).
CameraModel sceneCamera(const SceneConfig &config);

// People drawn at random image positions below the horizon, each a whole box inside the
// image; `frameStep` frames apart in time.
std::vector<PersonObservation> makeObservations(const SceneConfig &config, uint64_t frameStep = 1);

// Fits a SelfCalibrator to the observations.
SelfCalibrationVerdict calibrate(const std::vector<PersonObservation> &observations,
				 const SceneConfig &scene, SelfCalibrationResult &result,
				 SelfCalibrationConfig config = SelfCalibrationConfig());

} // namespace calped::selfcal_test
