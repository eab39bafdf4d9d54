// SPDX-License-Identifier: BSD-2-Clause
// Building blocks shared by the optimised gradient kernels (portable and SIMD): the
// row of doubled derivatives of the strongest colour channel, and the scalar
// per-pixel magnitude and orientation (the reference's arithmetic, used for tails).
#pragma once

#include "kernels.h"
#include "fixed_point.h"

namespace calped {
namespace kernels {

// Derivatives of row y of the channel with the largest squared magnitude into bx, by;
// cx, cy are scratch rows. All four hold width int32.
void strongestGradientRow(const uint16_t *const planes[3], ptrdiff_t stride, int width,
			  int height, int y, int32_t *bx, int32_t *by, int32_t *cx, int32_t *cy);

// Magnitude (Q16) and orientation of one pixel from its doubled derivatives.
inline void gradientPixel(const GradientTables &t, int32_t gx, int32_t gy, uint16_t *mag,
			  uint16_t *orient)
{
	const uint32_t m2 = uint32_t(gx * gx) + uint32_t(gy * gy);
	if (m2 == 0) {
		*mag = 0;
		*orient = t.fromCos[4096];
		return;
	}
	int m, k;
	normalizeEven(m2, m, k);
	*mag = saturateU16(shiftRound(int64_t(t.sqrtQ8[m]) << (k / 2), 9));
	const int64_t rs = t.rsqrtQ20[m];
	const int32_t gxf = gy < 0 ? -gx : gx;
	const int shift = 8 + k / 2;
	int64_t c12 = shiftRound(gxf * rs, shift);
	c12 = c12 < -4096 ? -4096 : (c12 > 4096 ? 4096 : c12);
	int64_t s12 = shiftRound((gy < 0 ? -gy : gy) * rs, shift);
	s12 = s12 > 4096 ? 4096 : s12;
	if (c12 >= -2896 && c12 <= 2896)
		*orient = t.fromCos[c12 + 4096];
	else
		*orient = c12 > 0 ? t.fromSinAcute[s12] : t.fromSinObtuse[s12];
}

} // namespace kernels
} // namespace calped
