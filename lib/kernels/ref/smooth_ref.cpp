// SPDX-License-Identifier: BSD-2-Clause
// Triangle smoothing, the reference: convTri with radius 1 ([1 2 1]/4 both ways,
// borders replicated) and the radius-r triangle sum used for gradient normalisation.
#include "kernels.h"
#include "fixed_point.h"

#include <algorithm>

namespace calped {
namespace kernels {

void smoothTri1_ref(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		    ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp)
{
	for (int y = 0; y < height; y++) {
		const uint16_t *above = src + std::max(y - 1, 0) * srcStride;
		const uint16_t *row = src + y * srcStride;
		const uint16_t *below = src + std::min(y + 1, height - 1) * srcStride;
		for (int x = 0; x < width; x++)
			rowTmp[x] = uint32_t(above[x]) + 2 * uint32_t(row[x]) + uint32_t(below[x]);
		uint16_t *out = dst + y * dstStride;
		for (int x = 0; x < width; x++) {
			const uint32_t left = rowTmp[std::max(x - 1, 0)];
			const uint32_t right = rowTmp[std::min(x + 1, width - 1)];
			out[x] = static_cast<uint16_t>((left + 2 * rowTmp[x] + right + 8) >> 4);
		}
	}
}

namespace {

// Index of a sample outside [0, n) under symmetric padding (edge sample repeated).
int reflect(int i, int n)
{
	while (i < 0 || i >= n) {
		if (i < 0)
			i = -i - 1;
		if (i >= n)
			i = 2 * n - i - 1;
	}
	return i;
}

} // namespace

void triSumR_ref(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		 int width, int height, int r, uint32_t *scratch)
{
	// Horizontal pass into dst (weights 1..r+1..1), then vertical pass in place through
	// one column of scratch.
	for (int y = 0; y < height; y++) {
		const uint16_t *row = src + y * srcStride;
		uint32_t *out = dst + y * dstStride;
		for (int x = 0; x < width; x++) {
			uint32_t acc = 0;
			for (int k = -r; k <= r; k++)
				acc += uint32_t(r + 1 - (k < 0 ? -k : k)) * row[reflect(x + k, width)];
			out[x] = acc;
		}
	}
	for (int x = 0; x < width; x++) {
		for (int y = 0; y < height; y++)
			scratch[y] = dst[y * dstStride + x];
		for (int y = 0; y < height; y++) {
			uint32_t acc = 0;
			for (int k = -r; k <= r; k++)
				acc += uint32_t(r + 1 - (k < 0 ? -k : k)) * scratch[reflect(y + k, height)];
			dst[y * dstStride + x] = acc;
		}
	}
}

} // namespace kernels
} // namespace calped
