// SPDX-License-Identifier: BSD-2-Clause
#include "detect/memory_estimate.h"

#include <algorithm>
#include <cmath>

#include "pyramid/ldcf_filter.h"

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
	double bytes = perPixel * pyramidPixels + kBytesPerInputPixel * inputPixels;
	// LDCF: each thread's filter stage holds one filtered channel of the largest padded
	// level and all 10 * nFilters half-size filtered channels with a stamp byte each (about
	// 8.25 bytes per pyramid pixel at shrink 2 with 4 filters), as Pyramid::setFilters
	// sizes them.
	if (params.nFilters > 0 && params.shrink > 0) {
		const double levelH = std::ceil((std::ceil(config.maxHeight * up) + 8) / params.shrink) + 2 +
				      2.0 * (params.padH / params.shrink);
		const double levelW = std::ceil((std::ceil(config.maxWidth * up) + 8) / params.shrink) + 2 +
				      2.0 * (params.padW / params.shrink);
		if (levelH < 1e9 && levelW < 1e9)
			bytes += double(std::max(config.threads, 1)) *
				 double(LdcfFilter::bytesFor(params.nFilters, uint64_t(levelH), uint64_t(levelW)));
		else
			bytes = 1.8e19;
	}
	return bytes >= 1.8e19 ? UINT64_MAX : uint64_t(bytes);
}

} // namespace calped
