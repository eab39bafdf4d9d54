// SPDX-License-Identifier: BSD-2-Clause
// The resize chosen from the camera (issue 16, item 3; docs/calibrated.md#resize-from-the-camera):
// the smallest upscaling at which the model's person height covers the smallest plausible
// person anywhere in the region of interest.
#pragma once

#include <calped/calibration.h>
#include <calped/model.h>
#include <calped/status.h>

namespace calped {

struct AutoResizeSettings {
	// The smallest plausible person, metres (CalibratedSettings::minPersonHeight).
	double minPersonHeight = 1.4;
	// The region of interest: ground within this distance of the point below the camera,
	// metres (> 0). Beyond it people are not looked for at their own size.
	double range = 30.0;
	// And only feet on this row or below (pixels; the default, -infinity, is every row):
	// self-calibration sets it to where it saw people.
	double minFootRow = -__builtin_inf();
	// The result is kept within [minResize, maxResize] (0 < min <= max <= 8).
	double minResize = 1.0;
	double maxResize = 4.0;
};

struct AutoResize {
	double resize = 1.0;
	// The smallest plausible person whose whole box lies in the frame and whose feet are on
	// ground in the region of interest: its height in input pixels and its foot's row.
	double smallestPersonPixels = 0;
	double footRow = 0;
	// The ground distance of that foot, metres.
	double distance = 0;
};

// Chooses the resize for width x height frames seen by `camera`: modelDsH / smallest person
// height, rounded up to the pyramid's scale step (a power of 2^(1/nPerOct)) and clamped to
// the settings' range. InvalidArgument when the settings are out of range or no plausible
// person fits in the frame within the region of interest.
Status chooseResize(const ModelParams &params, const CameraModel &camera, int width, int height,
		    const AutoResizeSettings &settings, AutoResize &out);

} // namespace calped
