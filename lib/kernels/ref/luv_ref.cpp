// SPDX-License-Identifier: BSD-2-Clause
// RGB8 -> LUV in Q16, the reference. Follows the toolbox's rgb2luv: XYZ from a linear
// matrix, L from the cube-root table indexed by floor(y * 1024), u and v from the
// chromaticity ratios scaled by L, offset to be non-negative.
#include "kernels.h"
#include "fixed_point.h"

namespace calped {
namespace kernels {

void rgbToLuv_ref(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		  int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride)
{
	for (int y = 0; y < height; y++) {
		const uint8_t *p = rgb + y * rgbStride;
		uint16_t *lo = l + y * stride, *uo = u + y * stride, *vo = v + y * stride;
		for (int x = 0; x < width; x++, p += 3) {
			const int32_t X = t.cx[0] * p[0] + t.cx[1] * p[1] + t.cx[2] * p[2]; // Q28
			const int32_t Y = t.cy[0] * p[0] + t.cy[1] * p[1] + t.cy[2] * p[2];
			const int32_t Z = t.cz[0] * p[0] + t.cz[1] * p[1] + t.cz[2] * p[2];
			const int32_t L = t.l[Y >> 18]; // Q16
			// d / 4 = x + 15 y + 3 z in Q26, so that it fits 31 bits.
			const int32_t d = (X >> 2) + 15 * (Y >> 2) + 3 * (Z >> 2);
			int64_t xd = 0, yd = 0; // x / d and y / d in Q20 (kLuvRatioQ)
			if (d > 0) {
				int m, k;
				normalize13(static_cast<uint64_t>(d), m, k);
				const int64_t r = t.rcp[m - 4096]; // 2^28 / m
				xd = shiftRound(int64_t(X) * r, 30 - kLuvRatioQ + k);
				yd = shiftRound(int64_t(Y) * r, 30 - kLuvRatioQ + k);
			}
			const int64_t uu = shiftRound(L * (52 * xd - t.un13), kLuvRatioQ) - t.minu;
			const int64_t vv = shiftRound(L * (117 * yd - t.vn13), kLuvRatioQ) - t.minv;
			lo[x] = static_cast<uint16_t>(L);
			uo[x] = saturateU16(uu);
			vo[x] = saturateU16(vv);
		}
	}
}

} // namespace kernels
} // namespace calped
