// SPDX-License-Identifier: BSD-2-Clause
// convTri with radius 1 with NEON: the vertical [1 2 1] into a uint32 row eight pixels at
// a time, then the horizontal [1 2 1] from three shifted loads of it and the rounding
// narrowing shift (v + 8) >> 4. Bit-identical to ref/smooth_ref.cpp.
#include <arm_neon.h>

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {

void smoothTri1_neon(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		     ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp)
{
	for (int y = 0; y < height; y++) {
		const uint16_t *a = src + std::max(y - 1, 0) * srcStride;
		const uint16_t *b = src + y * srcStride;
		const uint16_t *c = src + std::min(y + 1, height - 1) * srcStride;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			const uint16x8_t va = vld1q_u16(a + x), vb = vld1q_u16(b + x), vc = vld1q_u16(c + x);
			vst1q_u32(rowTmp + x, vaddq_u32(vaddl_u16(vget_low_u16(va), vget_low_u16(vc)),
							vshll_n_u16(vget_low_u16(vb), 1)));
			vst1q_u32(rowTmp + x + 4, vaddq_u32(vaddl_u16(vget_high_u16(va), vget_high_u16(vc)),
							    vshll_n_u16(vget_high_u16(vb), 1)));
		}
		for (; x < width; x++)
			rowTmp[x] = uint32_t(a[x]) + 2 * uint32_t(b[x]) + uint32_t(c[x]);

		uint16_t *out = dst + y * dstStride;
		if (width == 1) {
			out[0] = static_cast<uint16_t>((4 * rowTmp[0] + 8) >> 4);
			continue;
		}
		out[0] = static_cast<uint16_t>((3 * rowTmp[0] + rowTmp[1] + 8) >> 4);
		x = 1;
		for (; x + 8 <= width - 1; x += 8) {
			const uint32_t *t = rowTmp + x;
			const uint32x4_t lo = vaddq_u32(vaddq_u32(vld1q_u32(t - 1), vld1q_u32(t + 1)),
							vshlq_n_u32(vld1q_u32(t), 1));
			const uint32x4_t hi = vaddq_u32(vaddq_u32(vld1q_u32(t + 3), vld1q_u32(t + 5)),
							vshlq_n_u32(vld1q_u32(t + 4), 1));
			vst1q_u16(out + x, vcombine_u16(vrshrn_n_u32(lo, 4), vrshrn_n_u32(hi, 4)));
		}
		for (; x < width - 1; x++)
			out[x] = static_cast<uint16_t>((rowTmp[x - 1] + 2 * rowTmp[x] + rowTmp[x + 1] + 8) >> 4);
		out[width - 1] =
			static_cast<uint16_t>((rowTmp[width - 2] + 3 * rowTmp[width - 1] + 8) >> 4);
	}
}

} // namespace kernels
} // namespace calped
