// SPDX-License-Identifier: BSD-2-Clause
// Aggregation over 4x4 cells, the reference: block averages and orientation histograms.
#include "kernels.h"
#include "fixed_point.h"

#include <cstring>

namespace calped {
namespace kernels {

void shrink4_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	const int shift = 4 + extraShift;
	const int w4 = width / 4, h4 = height / 4;
	for (int cy = 0; cy < h4; cy++) {
		for (int cx = 0; cx < w4; cx++) {
			uint32_t acc = 0;
			for (int dy = 0; dy < 4; dy++) {
				const uint16_t *p = src + (4 * cy + dy) * srcStride + 4 * cx;
				acc += uint32_t(p[0]) + p[1] + p[2] + p[3];
			}
			dst[cy * dstStride + cx] = static_cast<uint16_t>((acc + (1u << (shift - 1))) >> shift);
		}
	}
}

void gradHist4_ref(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch)
{
	const int w4 = width / 4, h4 = height / 4;
	for (int cy = 0; cy < h4; cy++) {
		// scratch[o * w4 + cx]: sum of magnitude * weight (Q10) for orientation o.
		std::memset(scratch, 0, sizeof(uint32_t) * nOrients * w4);
		for (int dy = 0; dy < 4; dy++) {
			const uint16_t *mrow = mag + (4 * cy + dy) * stride;
			const uint16_t *orow = orient + (4 * cy + dy) * stride;
			for (int x = 0; x < 4 * w4; x++) {
				const uint32_t m = mrow[x];
				const int o = orow[x];
				uint32_t *cell = scratch + x / 4;
				if (interpolate) {
					const int o0 = o >> kOrientQ, f = o & ((1 << kOrientQ) - 1);
					const int o1 = o0 + 1 == nOrients ? 0 : o0 + 1;
					cell[o0 * w4] += m * uint32_t((1 << kOrientQ) - f);
					cell[o1 * w4] += m * uint32_t(f);
				} else {
					int b = (o + (1 << (kOrientQ - 1))) >> kOrientQ;
					if (b >= nOrients)
						b = 0;
					cell[b * w4] += m << kOrientQ;
				}
			}
		}
		for (int o = 0; o < nOrients; o++) {
			uint16_t *out = hist[o] + cy * histStride;
			for (int cx = 0; cx < w4; cx++)
				out[cx] = saturateU16((uint64_t(scratch[o * w4 + cx]) + (8u << kOrientQ)) >>
						     (4 + kOrientQ));
		}
	}
}

} // namespace kernels
} // namespace calped
