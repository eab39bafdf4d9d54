// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation, portable optimised build (see gradient_rows.h):
// derivatives and the channel maximum a row at a time in branch-free loops the compiler
// vectorises; the table lookups stay scalar. Bit-identical to ref/gradient_ref.cpp.
#include "opt/gradient_rows.h"

namespace calped {
namespace kernels {

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
