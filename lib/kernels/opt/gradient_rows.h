// SPDX-License-Identifier: BSD-2-Clause
// Building blocks shared by the optimised gradient kernels (portable and SIMD): the
// row of doubled derivatives of the strongest colour channel, and the scalar
// per-pixel magnitude and orientation (the reference's arithmetic, used for tails).
#pragma once

#include "kernels.h"
#include "fixed_point.h"

namespace calped {
namespace kernels {

// Internal linkage: every translation unit (portable, AVX2, ...) compiles its own copy
// with its own instruction set.
namespace {

inline int32_t clampDiff(int32_t v) { return v < -46340 ? -46340 : (v > 46340 ? 46340 : v); }

// Doubled derivatives of one row: horizontal from the row itself, vertical from the rows
// above and below; at the top and bottom the caller passes the row itself as one of them
// and vScale 2 (the one-sided difference), or 0 for a single-row image.
inline void rowDerivatives(const uint16_t *above, const uint16_t *row, const uint16_t *below,
		    int vScale, int width, int32_t *gx, int32_t *gy)
{
	if (width == 1) {
		gx[0] = 0;
	} else {
		gx[0] = clampDiff(2 * (int32_t(row[1]) - int32_t(row[0])));
		for (int x = 1; x < width - 1; x++)
			gx[x] = clampDiff(int32_t(row[x + 1]) - int32_t(row[x - 1]));
		gx[width - 1] = clampDiff(2 * (int32_t(row[width - 1]) - int32_t(row[width - 2])));
	}
	for (int x = 0; x < width; x++)
		gy[x] = clampDiff(vScale * (int32_t(below[x]) - int32_t(above[x])));
}

// Derivatives of row y of the channel with the largest squared magnitude into bx, by;
// cx, cy are scratch rows. All four hold width int32.
inline void strongestGradientRow(const uint16_t *const planes[3], ptrdiff_t stride, int width,
			  int height, int y, int32_t *bx, int32_t *by, int32_t *cx, int32_t *cy)
{
	const int up = y > 0 ? y - 1 : y, down = y < height - 1 ? y + 1 : y;
	const int vScale = height < 2 ? 0 : (y == 0 || y == height - 1 ? 2 : 1);
	for (int c = 0; c < 3; c++) {
		const uint16_t *p = planes[c];
		int32_t *gx = c == 0 ? bx : cx, *gy = c == 0 ? by : cy;
		rowDerivatives(p + up * stride, p + y * stride, p + down * stride, vScale, width, gx, gy);
		if (c == 0)
			continue;
		// Keep the channel with the larger squared magnitude (the earlier on ties).
		for (int x = 0; x < width; x++) {
			const uint32_t best = uint32_t(bx[x] * bx[x]) + uint32_t(by[x] * by[x]);
			const uint32_t cur = uint32_t(cx[x] * cx[x]) + uint32_t(cy[x] * cy[x]);
			const bool take = cur > best;
			bx[x] = take ? cx[x] : bx[x];
			by[x] = take ? cy[x] : by[x];
		}
	}
}

// The strongest channel's doubled derivatives at one pixel, borders as in rowDerivatives.
inline void strongestGradientAt(const uint16_t *const planes[3], ptrdiff_t stride, int width,
				int height, int x, int y, int32_t &gx, int32_t &gy)
{
	const int up = y > 0 ? y - 1 : y, down = y < height - 1 ? y + 1 : y;
	const int vScale = height < 2 ? 0 : (y == 0 || y == height - 1 ? 2 : 1);
	const int left = x > 0 ? x - 1 : x, right = x < width - 1 ? x + 1 : x;
	const int hScale = width < 2 ? 0 : (x == 0 || x == width - 1 ? 2 : 1);
	uint32_t best = 0;
	for (int c = 0; c < 3; c++) {
		const uint16_t *p = planes[c];
		const int32_t cx = clampDiff(hScale * (int32_t(p[y * stride + right]) - int32_t(p[y * stride + left])));
		const int32_t cy = clampDiff(vScale * (int32_t(p[down * stride + x]) - int32_t(p[up * stride + x])));
		const uint32_t m2 = uint32_t(cx * cx) + uint32_t(cy * cy);
		if (c == 0 || m2 > best) {
			best = m2;
			gx = cx;
			gy = cy;
		}
	}
}

// Magnitude (Q16) and orientation of one pixel from its doubled derivatives.
inline void gradientPixel(const GradientTables &t, int32_t gx, int32_t gy, uint16_t *mag,
			  uint16_t *orient)
{
	const uint32_t m2 = uint32_t(gx * gx) + uint32_t(gy * gy);
	if (m2 == 0) {
		*mag = 0;
		*orient = t.fromCos[kCosSteps];
		return;
	}
	int m, k;
	normalizeEven(m2, m, k);
	*mag = saturateU16(shiftRound(int64_t(t.sqrtQ8[m]) << (k / 2), 9));
	const int64_t p = (gy < 0 ? -gx : gx) * int64_t(t.rsqrtQ20[m]);
	int64_t c = ((p < 0 ? -p : p) * kCosSteps) >> (20 + k / 2);
	c = c > kCosSteps ? kCosSteps : c;
	*orient = t.fromCos[(p < 0 ? -c : c) + kCosSteps];
}

} // namespace
} // namespace kernels
} // namespace calped
