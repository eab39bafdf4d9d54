// SPDX-License-Identifier: BSD-2-Clause
// 2x2 aggregation (shrink 2) with NEON: block averages eight cells at a time; orientation
// histograms eight pixels at a time into the rows of per-pixel contributions that
// opt/hist2_body.h then sums into cells. Integer sums that fit 32 bits, so bit-identical
// to ref/aggregate2_ref.cpp; pixels and cells left over at the right use the portable body.
#include <arm_neon.h>

#include "kernels.h"
#include "opt/hist2_body.h"

namespace calped {
namespace kernels {

namespace {

// hist2AccumulateRow, eight pixels at a time: each pixel gives weight g to its bin and f to
// the next (interpolation), or 2^kOrientQ to its nearest bin; times its magnitude and wy.
void accumulateRowNeon(const uint16_t *mrow, const uint16_t *orow, int n, int nOrients,
		       bool interpolate, uint32_t wy, bool first, uint32_t *acc, size_t rowLength)
{
	const uint16x8_t one = vdupq_n_u16(1 << kOrientQ);
	int x = 0;
	for (; x + 8 <= n; x += 8) {
		const uint16x8_t o = vld1q_u16(orow + x), m = vld1q_u16(mrow + x);
		uint16x8_t bin, f, g;
		if (interpolate) {
			bin = vshrq_n_u16(o, kOrientQ);
			f = vandq_u16(o, vdupq_n_u16((1 << kOrientQ) - 1));
			g = vsubq_u16(one, f);
		} else {
			// (o + 2^(kOrientQ-1)) >> kOrientQ, the last bin's upper half wrapping to bin 0.
			const uint16x8_t nearest = vrshrq_n_u16(o, kOrientQ);
			bin = vbicq_u16(nearest, vcgeq_u16(nearest, vdupq_n_u16(uint16_t(nOrients))));
			f = vdupq_n_u16(0);
			g = one;
		}
		uint16x8_t inPrev = vceqq_u16(bin, vdupq_n_u16(uint16_t(nOrients - 1)));
		for (int b = 0; b < nOrients; b++) {
			const uint16x8_t in = vceqq_u16(bin, vdupq_n_u16(uint16_t(b)));
			// Added, not or-ed: with one bin, a pixel is in b and b - 1 both.
			const uint16x8_t w = vaddq_u16(vandq_u16(in, g), vandq_u16(inPrev, f));
			inPrev = in;
			uint32x4_t lo = vmulq_n_u32(vmull_u16(vget_low_u16(m), vget_low_u16(w)), wy);
			uint32x4_t hi = vmulq_n_u32(vmull_u16(vget_high_u16(m), vget_high_u16(w)), wy);
			uint32_t *a = acc + size_t(b) * rowLength + x;
			if (!first) {
				lo = vaddq_u32(lo, vld1q_u32(a));
				hi = vaddq_u32(hi, vld1q_u32(a + 4));
			}
			vst1q_u32(a, lo);
			vst1q_u32(a + 4, hi);
		}
	}
	if (x < n)
		hist2AccumulateRow(mrow + x, orow + x, n - x, nOrients, interpolate, wy, first, acc + x,
				   rowLength);
}

} // namespace

void shrink2_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	const int w2 = width / 2, h2 = height / 2;
	const int shift = 2 + extraShift;
	const int32x4_t right = vdupq_n_s32(-shift);
	for (int cy = 0; cy < h2; cy++) {
		const uint16_t *r0 = src + 2 * cy * srcStride, *r1 = r0 + srcStride;
		uint16_t *out = dst + cy * dstStride;
		int cx = 0;
		for (; cx + 8 <= w2; cx += 8) {
			// Pairs of neighbours in each row, the two rows added: four cells per vector.
			const uint32x4_t a = vpadalq_u16(vpaddlq_u16(vld1q_u16(r0 + 2 * cx)), vld1q_u16(r1 + 2 * cx));
			const uint32x4_t b = vpadalq_u16(vpaddlq_u16(vld1q_u16(r0 + 2 * cx + 8)),
							 vld1q_u16(r1 + 2 * cx + 8));
			// Rounding shift: (sum + 2^(shift-1)) >> shift, as the reference.
			vst1q_u16(out + cx, vcombine_u16(vmovn_u32(vrshlq_u32(a, right)),
							 vmovn_u32(vrshlq_u32(b, right))));
		}
		for (; cx < w2; cx++)
			out[cx] = static_cast<uint16_t>((uint32_t(r0[2 * cx]) + r0[2 * cx + 1] + r1[2 * cx] +
							 r1[2 * cx + 1] + (1u << (shift - 1))) >> shift);
	}
}

void gradHist2_neon(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist2Rows(mag, orient, stride, width, height, nOrients, interpolate, spatial, hist,
		      histStride, scratch, accumulateRowNeon);
}

} // namespace kernels
} // namespace calped
