// SPDX-License-Identifier: BSD-2-Clause
// Triangle sum of radius r with NEON. The horizontal pass, a running sum per row in the
// portable build, is here a direct 2r+1-tap convolution of eight pixels at a time
// (widening multiply-accumulates of the source row; the r pixels at each end, which need
// the symmetric padding, are summed one by one). The vertical pass is the portable
// one (smooth_body.h), whose loops over whole rows the compiler vectorises. Integer sums,
// so bit-identical to ref/smooth_ref.cpp.
#include <arm_neon.h>

#include "opt/smooth_body.h"

namespace calped {
namespace kernels {

namespace {

inline uint32_t triangleWeight(int k, int r) { return uint32_t(r + 1 - (k < r ? r - k : k - r)); }

// One row of the horizontal pass: out[x] = sum over k of weight(k) * row[x + k - r], the
// row padded symmetrically.
void triangleRowNeon(const uint16_t *row, int width, int r, uint32_t *out)
{
	auto scalar = [&](int x) {
		uint32_t acc = 0;
		for (int k = 0; k <= 2 * r; k++)
			acc += triangleWeight(k, r) * row[reflect(x + k - r, width)];
		out[x] = acc;
	};
	int x = 0;
	for (; x < r && x < width; x++)
		scalar(x);
	// Inner pixels read the source row itself: x - r >= 0 and x + 7 + r < width.
	for (; x + 8 + r <= width; x += 8) {
		const uint16_t *p = row + x - r;
		uint32x4_t lo = vdupq_n_u32(0), hi = vdupq_n_u32(0);
		for (int k = 0; k <= 2 * r; k++) {
			const uint16x8_t v = vld1q_u16(p + k);
			const uint16_t w = uint16_t(triangleWeight(k, r));
			lo = vmlal_n_u16(lo, vget_low_u16(v), w);
			hi = vmlal_n_u16(hi, vget_high_u16(v), w);
		}
		vst1q_u32(out + x, lo);
		vst1q_u32(out + x + 4, hi);
	}
	for (; x < width; x++)
		scalar(x);
}

} // namespace

void triSumR_neon(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		  int width, int height, int r, uint32_t *scratch)
{
	const TriSumScratch s(scratch, width, height, r);
	for (int y = 0; y < height; y++)
		triangleRowNeon(src + y * srcStride, width, r, s.horiz + size_t(y) * width);
	triSumColumnsBody(s, dst, dstStride, width, height, r);
}

} // namespace kernels
} // namespace calped
