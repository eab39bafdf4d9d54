// SPDX-License-Identifier: BSD-2-Clause
// Triangle sum of radius r with NEON. The horizontal pass, a running sum per row in the
// portable build, is here a direct 2r+1-tap convolution of eight pixels at a time
// (widening multiply-accumulates of the source row, unrolled for r up to 8; the r pixels
// at each end, which need the symmetric padding, are summed one by one). The vertical
// pass keeps the portable build's two running sums (smooth_body.h), fused into one loop
// over each row. Integer sums, so bit-identical to ref/smooth_ref.cpp.
#include <arm_neon.h>

#include "opt/smooth_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr uint32_t triangleWeight(int k, int r) { return uint32_t(r + 1 - (k < r ? r - k : k - r)); }

// One row of the horizontal pass: out[x] = sum over k of weight(k) * row[x + k - r], the
// row padded symmetrically. R > 0: r = R, unrolled; R = 0: any r.
template <int R>
void triangleRow(const uint16_t *row, int width, int r, uint32_t *out)
{
	if constexpr (R > 0)
		r = R;
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
#pragma GCC unroll 17
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

template <int R>
void horizontalPass(const uint16_t *src, ptrdiff_t srcStride, int width, int height, int r,
		    uint32_t *horiz)
{
	for (int y = 0; y < height; y++)
		triangleRow<R>(src + y * srcStride, width, r, horiz + size_t(y) * width);
}

// The vertical pass of triSumColumnsBody with its two loops over a row fused, four
// columns at a time.
void verticalPass(const TriSumScratch &s, uint32_t *dst, ptrdiff_t dstStride, int width,
		  int height, int r)
{
	auto q = [&](int m) { return triSumPaddedRow(s, m, width, height, r); };
	uint32_t *acc1 = s.acc1, *acc2 = s.acc2;
	triSumColumnsStart(s, width, height, r);
	for (int m = 0; m < height + r; m++) {
		const uint32_t *in = q(m + r);
		const uint32_t *leaving = q(m);
		uint32_t *box = s.ring + size_t(m % (r + 1)) * width;
		const bool emit = m >= r;
		uint32_t *out = emit ? dst + (m - r) * dstStride : nullptr;
		// Box row m - r, the oldest in acc2's window once it is full (with r = 0 it is
		// row m itself, hence the store of row m first).
		const uint32_t *oldest = emit ? s.ring + size_t((m - r) % (r + 1)) * width : nullptr;
		int x = 0;
		for (; x + 4 <= width; x += 4) {
			const uint32x4_t a1 = vaddq_u32(vld1q_u32(acc1 + x), vld1q_u32(in + x));
			uint32x4_t a2 = vaddq_u32(vld1q_u32(acc2 + x), a1);
			vst1q_u32(box + x, a1);
			vst1q_u32(acc1 + x, vsubq_u32(a1, vld1q_u32(leaving + x)));
			if (emit) {
				vst1q_u32(out + x, a2);
				a2 = vsubq_u32(a2, vld1q_u32(oldest + x));
			}
			vst1q_u32(acc2 + x, a2);
		}
		for (; x < width; x++) {
			const uint32_t a1 = acc1[x] + in[x];
			uint32_t a2 = acc2[x] + a1;
			box[x] = a1;
			acc1[x] = a1 - leaving[x];
			if (emit) {
				out[x] = a2;
				a2 -= oldest[x];
			}
			acc2[x] = a2;
		}
	}
}

} // namespace

void triSumR_neon(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		  int width, int height, int r, uint32_t *scratch)
{
	const TriSumScratch s(scratch, width, height, r);
	switch (r) {
	case 1: horizontalPass<1>(src, srcStride, width, height, r, s.horiz); break;
	case 2: horizontalPass<2>(src, srcStride, width, height, r, s.horiz); break;
	case 3: horizontalPass<3>(src, srcStride, width, height, r, s.horiz); break;
	case 4: horizontalPass<4>(src, srcStride, width, height, r, s.horiz); break;
	case 5: horizontalPass<5>(src, srcStride, width, height, r, s.horiz); break;
	case 6: horizontalPass<6>(src, srcStride, width, height, r, s.horiz); break;
	case 7: horizontalPass<7>(src, srcStride, width, height, r, s.horiz); break;
	case 8: horizontalPass<8>(src, srcStride, width, height, r, s.horiz); break;
	default: horizontalPass<0>(src, srcStride, width, height, r, s.horiz); break;
	}
	verticalPass(s, dst, dstStride, width, height, r);
}

} // namespace kernels
} // namespace calped
