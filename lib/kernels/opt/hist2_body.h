// SPDX-License-Identifier: BSD-2-Clause
// Bodies of the optimised 2x2 aggregation kernels (shrink 2: Caltech+, LDCF), shared by the
// portable, AVX2 and NEON builds. As in hist_body.h, every orientation bin gets a row of
// per-pixel contributions (branch-free loops the compiler vectorises) instead of the
// reference's scatter into 64-bit sums; the cell sums then fit 32 bits:
// magnitude (< 2^16) x orientation weight (<= 2^kOrientQ) x spatial weights (the toolbox's
// bilinear 1, 3, 3, 1 each way, 64 in all) <= 65535 * 2^16 < 2^32.
// Integer sums in a different order, so bit-identical to ref/aggregate2_ref.cpp.
#pragma once

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

// Scratch the histogram body needs: one cell row's vertical sums per bin, with a zero on
// each side (within kernels.h's 2 * nOrients * width for width >= 2).
inline size_t hist2RowLength(int width) { return size_t(width / 2) * 2 + 2; }

// Pixel row `y`'s contributions to bin b, times the row's vertical weight wy, into
// acc + b * rowLength (overwriting when `first`, else adding) for x < n.
inline void hist2AccumulateRow(const uint16_t *mrow, const uint16_t *orow, int n, int nOrients,
			       bool interpolate, uint32_t wy, bool first, uint32_t *acc,
			       size_t rowLength)
{
	const uint32_t one = 1u << kOrientQ, fracMask = one - 1;
	const uint32_t keep = first ? 0 : ~0u;
	for (int b = 0; b < nOrients; b++) {
		uint32_t *a = acc + size_t(b) * rowLength;
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
			a[x] = (a[x] & keep) + m * w * wy;
		}
	}
}

// Cell row cy of every bin from the vertical sums (v[-1] and v[n] are the zero sides).
inline void hist2EmitCellRow(uint32_t *acc, size_t rowLength, int w2, int h2, int cy,
			     int nOrients, bool spatial, uint16_t *const *hist, ptrdiff_t histStride)
{
	const int n = 2 * w2;
	const bool borderY = cy == 0 || cy == h2 - 1;
	for (int b = 0; b < nOrients; b++) {
		uint32_t *row = acc + size_t(b) * rowLength;
		row[0] = 0;
		row[n + 1] = 0;
		const uint32_t *v = row + 1;
		uint16_t *out = hist[b] + cy * histStride;
		if (!spatial) {
			// The reference's (16 s + 2^15) >> 16 with s the cell's sum (< 2^28).
			for (int cx = 0; cx < w2; cx++) {
				const uint32_t s = v[2 * cx] + v[2 * cx + 1];
				const uint32_t q = (s + (1u << 11)) >> 12;
				out[cx] = static_cast<uint16_t>(q > 65535 ? 65535 : q);
			}
			continue;
		}
		for (int cx = 0; cx < w2; cx++) {
			const uint32_t a = v[2 * cx - 1] + 3 * (v[2 * cx] + v[2 * cx + 1]) + v[2 * cx + 2];
			uint64_t q;
			if (!borderY && cx != 0 && cx != w2 - 1) {
				// a * 49 / (49 * 2^16), rounded: (a + 2^15) >> 16 without leaving 32 bits.
				q = (a >> 16) + ((a >> 15) & 1u);
			} else {
				// Border cells times 8/7 (corners twice), as the reference.
				const uint64_t num = uint64_t(a) * (borderY ? 8 : 7) *
						     (cx == 0 || cx == w2 - 1 ? 8 : 7);
				const uint64_t den = uint64_t(49) << 16;
				q = (num + den / 2) / den;
			}
			out[cx] = static_cast<uint16_t>(q > 65535 ? 65535 : q);
		}
	}
}

// Rows of cell row cy and their vertical weights: with spatial binning 2cy - 1, 2cy,
// 2cy + 1, 2cy + 2 weigh 1, 3, 3, 1 (those inside the 2 h2 rows); else 2cy and 2cy + 1.
template <typename AccumulateRow>
inline void gradHist2Rows(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride,
			  int width, int height, int nOrients, bool interpolate, bool spatial,
			  uint16_t *const *hist, ptrdiff_t histStride, uint32_t *scratch,
			  AccumulateRow accumulateRow)
{
	const int w2 = width / 2, h2 = height / 2, n = 2 * w2;
	if (w2 == 0 || h2 == 0)
		return;
	const size_t rowLength = hist2RowLength(width);
	uint32_t *acc = scratch + 1; // v[-1] at scratch[0]
	for (int cy = 0; cy < h2; cy++) {
		bool first = true;
		for (int dy = spatial ? -1 : 0; dy <= (spatial ? 2 : 1); dy++) {
			const int y = 2 * cy + dy;
			if (y < 0 || y >= 2 * h2)
				continue;
			const uint32_t wy = !spatial ? 1u : (dy == 0 || dy == 1 ? 3u : 1u);
			accumulateRow(mag + y * stride, orient + y * stride, n, nOrients, interpolate, wy,
				      first, acc, rowLength);
			first = false;
		}
		hist2EmitCellRow(scratch, rowLength, w2, h2, cy, nOrients, spatial, hist, histStride);
	}
}

inline void gradHist2Body(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride,
			  int width, int height, int nOrients, bool interpolate, bool spatial,
			  uint16_t *const *hist, ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist2Rows(mag, orient, stride, width, height, nOrients, interpolate, spatial, hist,
		      histStride, scratch, hist2AccumulateRow);
}

inline void shrink2Body(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
			uint16_t *dst, ptrdiff_t dstStride, int extraShift)
{
	const int w2 = width / 2, h2 = height / 2;
	const int shift = 2 + extraShift;
	const uint32_t half = 1u << (shift - 1);
	for (int cy = 0; cy < h2; cy++) {
		const uint16_t *r0 = src + 2 * cy * srcStride, *r1 = r0 + srcStride;
		uint16_t *out = dst + cy * dstStride;
		for (int cx = 0; cx < w2; cx++)
			out[cx] = static_cast<uint16_t>((uint32_t(r0[2 * cx]) + r0[2 * cx + 1] +
							 r1[2 * cx] + r1[2 * cx + 1] + half) >> shift);
	}
}

} // namespace
} // namespace kernels
} // namespace calped
