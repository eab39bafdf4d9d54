// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation restructured for speed: derivatives and the
// channel maximum are computed a row at a time in branch-free loops the compiler
// vectorises; the table lookups stay scalar. Bit-identical to ref/gradient_ref.cpp.
#include "opt/gradient_rows.h"

namespace calped {
namespace kernels {

namespace {

inline int32_t clampDiff(int32_t v) { return v < -46340 ? -46340 : (v > 46340 ? 46340 : v); }

// Doubled derivatives of one row: horizontal from the row itself, vertical from the rows
// above and below; at the top and bottom the caller passes the row itself as one of them
// and vScale 2 (the one-sided difference), or 0 for a single-row image.
void rowDerivatives(const uint16_t *above, const uint16_t *row, const uint16_t *below,
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

} // namespace

void strongestGradientRow(const uint16_t *const planes[3], ptrdiff_t stride, int width,
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

void gradMagOrient_opt(const GradientTables &t, const uint16_t *const planes[3],
		       ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
		       ptrdiff_t outStride, int32_t *scratch)
{
	int32_t *bx = scratch, *by = bx + width, *cx = by + width, *cy = cx + width;
	for (int y = 0; y < height; y++) {
		strongestGradientRow(planes, stride, width, height, y, bx, by, cx, cy);
		uint16_t *mo = mag + y * outStride;
		uint16_t *oo = orient + y * outStride;
		for (int x = 0; x < width; x++)
			gradientPixel(t, bx[x], by[x], mo + x, oo + x);
	}
}

} // namespace kernels
} // namespace calped
