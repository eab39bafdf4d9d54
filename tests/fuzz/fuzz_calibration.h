// SPDX-License-Identifier: BSD-2-Clause
// What every calibration fuzz target checks after a loader returned: a failure's message
// names the file and is one printable line (docs/errors.md); a success is a valid camera
// whose geometry can be evaluated (NaN is allowed where documented, faults are not).
#pragma once

#include <cstdlib>

#include <calped/calibration.h>

#include "fuzz_checks.h"

namespace calped::fuzz {

inline void checkCalibration(const Status &st, const CameraModel &camera, const char *name)
{
	if (!st.ok()) {
		if (!namesFile(st.message(), name))
			fail("the message names the file on one printable line", st.message());
		return;
	}
	if (!camera.valid() || !camera.projection().allFinite())
		fail("a loaded camera is valid and finite", "");
	// Exercise the geometry a detector would use; results may be NaN, never a fault.
	const Eigen::Vector2d pixel(100.0, 400.0);
	Eigen::Vector2d ground;
	volatile double sink = camera.boxPixelHeight(pixel, 1.7);
	sink = camera.horizonRow(320.0);
	if (camera.pixelToGround(pixel, ground))
		sink = ground.x();
	sink = camera.worldToPixel(Eigen::Vector3d(1.0, 2.0, 0.0)).x();
	(void)sink;
}

} // namespace calped::fuzz
