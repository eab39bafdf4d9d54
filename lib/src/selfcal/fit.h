// SPDX-License-Identifier: BSD-2-Clause
// The self-calibration fit over a buffer of head/foot observations (fit.cpp).
#pragma once

#include <vector>

#include <calped/self_calibration.h>

namespace calped {

// World-to-camera rotation of a camera looking along +y, tilted down by `tilt` and rolled.
Eigen::Matrix3d selfCalibrationRotation(double tilt, double roll);

// The verdict and, when Ok, the camera; `observations` oldest first. Allocates.
SelfCalibrationVerdict fitSelfCalibration(const std::vector<PersonObservation> &observations,
					  int imageWidth, int imageHeight,
					  const SelfCalibrationConfig &config,
					  SelfCalibrationResult &out);

} // namespace calped
