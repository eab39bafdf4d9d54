// SPDX-License-Identifier: BSD-2-Clause
// The last step of a frame with a camera: where each detected person stands on the
// ground (the box's bottom centre) and how tall the box is in the world.
#pragma once

#include <calped/calibration.h>
#include <calped/detector.h>

namespace calped {

void addWorldCoordinates(const CameraModel &camera, Detection *boxes, int count);

} // namespace calped
