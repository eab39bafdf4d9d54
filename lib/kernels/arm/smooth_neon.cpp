// SPDX-License-Identifier: BSD-2-Clause
// convTri with radius 1 with NEON, one pass per row: the vertical [1 2 1] of eight pixels
// at a time stays in registers, and the horizontal neighbours come from the blocks before
// and after it by lane extraction; (v + 8) >> 4 is the rounding narrowing shift. The row
// ends replicate their pixel as the reference does; a row's last pixels are its last block
// of eight, overlapping the one before. Bit-identical to ref/smooth_ref.cpp.
#include <arm_neon.h>

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {

namespace {

// Vertical sums above + 2 * row + below of eight pixels.
struct Vertical8 {
	uint32x4_t lo, hi;
};

inline Vertical8 vertical8(const uint16_t *a, const uint16_t *b, const uint16_t *c)
{
	const uint16x8_t va = vld1q_u16(a), vb = vld1q_u16(b), vc = vld1q_u16(c);
	return { vmlal_n_u16(vaddl_u16(vget_low_u16(va), vget_low_u16(vc)), vget_low_u16(vb), 2),
		 vmlal_n_u16(vaddl_u16(vget_high_u16(va), vget_high_u16(vc)), vget_high_u16(vb), 2) };
}

} // namespace

void smoothTri1_neon(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		     ptrdiff_t dstStride, int width, int height, uint32_t *)
{
	for (int y = 0; y < height; y++) {
		const uint16_t *a = src + std::max(y - 1, 0) * srcStride;
		const uint16_t *b = src + y * srcStride;
		const uint16_t *c = src + std::min(y + 1, height - 1) * srcStride;
		uint16_t *out = dst + y * dstStride;
		// The vertical sum at x, replicated past the row ends.
		auto vertical = [&](int x) {
			x = std::clamp(x, 0, width - 1);
			return uint32_t(a[x]) + 2 * uint32_t(b[x]) + uint32_t(c[x]);
		};
		int x = 0;
		if (width >= 8) {
			// Lane 3 of `before` is the vertical sum left of the block: at x = 0, the
			// replicated first pixel.
			uint32x4_t before = vdupq_n_u32(vertical(0));
			Vertical8 cur = vertical8(a, b, c);
			for (; x + 8 <= width; x += 8) {
				// Lane 0 of next.lo is the vertical sum right of the block.
				Vertical8 next;
				if (x + 16 <= width)
					next = vertical8(a + x + 8, b + x + 8, c + x + 8);
				else
					next.lo = next.hi = vdupq_n_u32(vertical(x + 8));
				const uint32x4_t leftLo = vextq_u32(before, cur.lo, 3);
				const uint32x4_t leftHi = vextq_u32(cur.lo, cur.hi, 3);
				const uint32x4_t rightLo = vextq_u32(cur.lo, cur.hi, 1);
				const uint32x4_t rightHi = vextq_u32(cur.hi, next.lo, 1);
				const uint32x4_t lo = vmlaq_n_u32(vaddq_u32(leftLo, rightLo), cur.lo, 2);
				const uint32x4_t hi = vmlaq_n_u32(vaddq_u32(leftHi, rightHi), cur.hi, 2);
				vst1q_u16(out + x, vcombine_u16(vrshrn_n_u32(lo, 4), vrshrn_n_u32(hi, 4)));
				before = cur.hi;
				cur = next;
			}
			// The last pixels as the row's last block of eight, overlapping the one
			// before (the same values written again).
			if (x < width) {
				const int last = width - 8;
				const Vertical8 v = vertical8(a + last, b + last, c + last);
				const uint32x4_t left = vdupq_n_u32(vertical(last - 1));
				const uint32x4_t right = vdupq_n_u32(vertical(width));
				const uint32x4_t lo = vmlaq_n_u32(vaddq_u32(vextq_u32(left, v.lo, 3), vextq_u32(v.lo, v.hi, 1)), v.lo, 2);
				const uint32x4_t hi = vmlaq_n_u32(vaddq_u32(vextq_u32(v.lo, v.hi, 3), vextq_u32(v.hi, right, 1)), v.hi, 2);
				vst1q_u16(out + last, vcombine_u16(vrshrn_n_u32(lo, 4), vrshrn_n_u32(hi, 4)));
				x = width;
			}
		}
		for (; x < width; x++)
			out[x] = static_cast<uint16_t>(
				(vertical(x - 1) + 2 * vertical(x) + vertical(x + 1) + 8) >> 4);
	}
}

} // namespace kernels
} // namespace calped
