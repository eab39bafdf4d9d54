// SPDX-License-Identifier: BSD-2-Clause
#include "detect/memory_estimate.h"

#include <algorithm>
#include <cmath>

namespace calped {

namespace {

// Bytes per pixel of the largest pyramid image, shared (the computed levels' channels at
// 4/3 of the first, the smoothed and padded level) and per thread (each thread's scratch:
// three LUV planes, the resampling buffer, the gradient, normalisation and histogram
// buffers), and per input pixel (the frame's colour planes and half-size planes, the
// resized frame, the static background), from the buffer types of pyramid.cpp, the
// channel computer and input_stage. Allocated, not resident: most scratch pages stay
// untouched zero pages (docs/benchmarks.md measures what is resident).
constexpr double kSharedBytesPerPyramidPixel = 12;
constexpr double kThreadBytesPerPyramidPixel = 28;
constexpr double kBytesPerInputPixel = 16;

} // namespace

uint64_t estimateDetectorBytes(const ModelParams &params, const DetectorConfig &config)
{
	const double up = config.resize * std::ldexp(1.0, params.nOctUp);
	const double pyramidPixels = (std::ceil(config.maxWidth * up) + 8) * (std::ceil(config.maxHeight * up) + 8);
	const double inputPixels = double(config.maxWidth) * config.maxHeight;
	const double perPixel = kSharedBytesPerPyramidPixel + kThreadBytesPerPyramidPixel * std::max(1, config.threads);
	const double bytes = perPixel * pyramidPixels + kBytesPerInputPixel * inputPixels;
	return bytes >= 1.8e19 ? UINT64_MAX : uint64_t(bytes);
}

} // namespace calped
