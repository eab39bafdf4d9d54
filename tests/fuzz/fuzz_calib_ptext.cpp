// SPDX-License-Identifier: BSD-2-Clause
// loadProjectionText on arbitrary bytes: plain projection-matrix text.
#include <cstddef>
#include <cstdint>

#include <calped/calibration.h>

#include "fuzz_calibration.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const char *name = "fuzz.txt";
	calped::CameraModel camera;
	const calped::Status st =
		calped::loadProjectionText(reinterpret_cast<const char *>(data), size, name, camera);
	calped::fuzz::checkCalibration(st, camera, name);
	return 0;
}
