// SPDX-License-Identifier: BSD-2-Clause
// Bodies of the optimised 4x4 aggregation kernels, shared by the portable and SIMD
// builds. Rows are accumulated in branch-free loops the compiler vectorises, then groups
// of four are summed: the histograms give every orientation bin a row of per-pixel
// contributions instead of scattering each pixel into its cell (the reference). Integer
// sums, so bit-identical to ref/aggregate_ref.cpp.
#pragma once

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

// scratch: width uint32.
inline void shrink4Body(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
			uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch)
{
	const int w4 = width / 4, h4 = height / 4, n = 4 * w4;
	const int shift = 4 + extraShift;
	const uint32_t half = 1u << (shift - 1);
	for (int cy = 0; cy < h4; cy++) {
		const uint16_t *r0 = src + 4 * cy * srcStride, *r1 = r0 + srcStride;
		const uint16_t *r2 = r1 + srcStride, *r3 = r2 + srcStride;
		for (int x = 0; x < n; x++)
			scratch[x] = uint32_t(r0[x]) + r1[x] + r2[x] + r3[x];
		uint16_t *out = dst + cy * dstStride;
		for (int cx = 0; cx < w4; cx++) {
			const uint32_t *a = scratch + 4 * cx;
			out[cx] = static_cast<uint16_t>((a[0] + a[1] + a[2] + a[3] + half) >> shift);
		}
	}
}

inline void gradHist4Body(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride,
			  int width, int height, int nOrients, bool interpolate,
			  uint16_t *const *hist, ptrdiff_t histStride, uint32_t *scratch)
{
	const int w4 = width / 4, h4 = height / 4, n = 4 * w4;
	const uint32_t one = 1u << kOrientQ, fracMask = one - 1;
	// scratch: nOrients rows of n per-pixel sums over the cell's four rows.
	for (int cy = 0; cy < h4; cy++) {
		for (int dy = 0; dy < 4; dy++) {
			// The first of the cell's rows starts the sums (no separate clearing pass).
			const uint32_t keep = dy == 0 ? 0 : ~0u;
			const uint16_t *mrow = mag + (4 * cy + dy) * stride;
			const uint16_t *orow = orient + (4 * cy + dy) * stride;
			for (int b = 0; b < nOrients; b++) {
				uint32_t *acc = scratch + size_t(b) * n;
				const uint32_t prev = b == 0 ? uint32_t(nOrients - 1) : uint32_t(b - 1);
				for (int x = 0; x < n; x++) {
					const uint32_t o = orow[x], m = mrow[x];
					uint32_t w;
					if (interpolate) {
						const uint32_t o0 = o >> kOrientQ, f = o & fracMask;
						w = (o0 == uint32_t(b) ? one - f : 0) + (o0 == prev ? f : 0);
					} else {
						uint32_t nearest = (o + (one >> 1)) >> kOrientQ;
						nearest = nearest >= uint32_t(nOrients) ? 0 : nearest;
						w = nearest == uint32_t(b) ? one : 0;
					}
					acc[x] = (acc[x] & keep) + m * w;
				}
			}
		}
		for (int b = 0; b < nOrients; b++) {
			const uint32_t *acc = scratch + size_t(b) * n;
			uint16_t *out = hist[b] + cy * histStride;
			for (int cx = 0; cx < w4; cx++) {
				const uint64_t s = uint64_t(acc[4 * cx]) + acc[4 * cx + 1] + acc[4 * cx + 2] +
						   acc[4 * cx + 3];
				const uint64_t v = (s + (8u << kOrientQ)) >> (4 + kOrientQ);
				out[cx] = static_cast<uint16_t>(v > 65535 ? 65535 : v);
			}
		}
	}
}

} // namespace
} // namespace kernels
} // namespace calped
