// SPDX-License-Identifier: BSD-2-Clause
#include "detect/memory_estimate.h"

#include <cmath>

namespace calped {

namespace {

// Bytes per pixel of the largest pyramid image (three LUV planes, the resampling buffer,
// gradient and histogram buffers, the computed levels' channels at 4/3 of the first)
// and per input pixel (the frame's colour planes and half-size planes, the resized
// frame, the static background), from the buffer types of pyramid.cpp and input_stage:
// measured peaks are 33-38 bytes per pyramid pixel (docs/errors.md).
constexpr double kBytesPerPyramidPixel = 40;
constexpr double kBytesPerInputPixel = 16;

} // namespace

uint64_t estimateDetectorBytes(const ModelParams &params, const DetectorConfig &config)
{
	const double up = config.resize * std::ldexp(1.0, params.nOctUp);
	const double pyramidPixels = (std::ceil(config.maxWidth * up) + 8) * (std::ceil(config.maxHeight * up) + 8);
	const double inputPixels = double(config.maxWidth) * config.maxHeight;
	const double bytes = kBytesPerPyramidPixel * pyramidPixels + kBytesPerInputPixel * inputPixels;
	return bytes >= 1.8e19 ? UINT64_MAX : uint64_t(bytes);
}

} // namespace calped
