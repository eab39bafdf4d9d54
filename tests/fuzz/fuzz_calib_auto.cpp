// SPDX-License-Identifier: BSD-2-Clause
// loadCalibration on arbitrary bytes: format detection, then whichever loader it picks.
#include <cstddef>
#include <cstdint>

#include <calped/calibration.h>

#include "fuzz_calibration.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *name = "fuzz.cal";
	calped::CameraModel camera;
	const calped::Status st =
		calped::loadCalibration(reinterpret_cast<const char *>(data), size, name, camera);
	calped::fuzz::checkCalibration(st, camera, name);
	return 0;
}
