// SPDX-License-Identifier: BSD-2-Clause
// The pyramid's scale list, exactly as the toolbox's chnsPyramid/getScales builds it.
#pragma once

#include <calped/model.h>

namespace calped {

constexpr int kMaxLevels = 128;

struct PyramidLevel {
	double scale = 0;        // nominal scale
	double scaleH = 0;       // actual vertical scale: rounded size / input size
	double scaleW = 0;       // actual horizontal scale
	int height = 0;          // channel size in cells (before padding)
	int width = 0;
	bool computed = false;   // channels computed from the image at this scale
	int source = 0;          // computed level this one is approximated from (itself if computed)
};

struct ScaleList {
	int count = 0;
	PyramidLevel levels[kMaxLevels];
};

// Fill `out` for an image of height x width pixels. Returns false if the model's
// parameters would need more than kMaxLevels levels. `upscale` > 1 starts the pyramid
// that much above the image, on top of the model's nOctUp: the toolbox's nOctUp
// generalised to any factor (upscale 2 is nOctUp + 1 exactly), which gives the levels of
// the image resized by `upscale` without resizing it.
bool computeScales(const ModelParams &p, int height, int width, ScaleList &out,
		   double upscale = 1.0);

} // namespace calped
