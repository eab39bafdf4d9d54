// SPDX-License-Identifier: BSD-2-Clause
// 4x4 aggregation with NEON: block averages four cells at a time, orientation histograms
// two cells at a time. Integer sums that fit 32 bits (16 * 65535 * 2^kOrientQ < 2^31), so
// bit-identical to ref/aggregate_ref.cpp; cells left over at the right use the reference's
// arithmetic.
#include <arm_neon.h>

#include "kernels.h"
#include "fixed_point.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

// One cell of the histograms, as the reference computes it; bins holds nOrients uint32.
void histCell(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int nOrients,
	      bool interpolate, uint32_t *bins)
{
	for (int b = 0; b < nOrients; b++)
		bins[b] = 0;
	for (int dy = 0; dy < 4; dy++)
		for (int dx = 0; dx < 4; dx++) {
			const uint32_t m = mag[dy * stride + dx];
			const int o = orient[dy * stride + dx];
			if (interpolate) {
				const int o0 = o >> kOrientQ, f = o & ((1 << kOrientQ) - 1);
				const int o1 = o0 + 1 == nOrients ? 0 : o0 + 1;
				bins[o0] += m * uint32_t((1 << kOrientQ) - f);
				bins[o1] += m * uint32_t(f);
			} else {
				int b = (o + (1 << (kOrientQ - 1))) >> kOrientQ;
				if (b >= nOrients)
					b = 0;
				bins[b] += m << kOrientQ;
			}
		}
}

// Eight pixels of one row split into bin weights: the pixel gives weight g to `bin` and f
// to the next bin (interpolation), or 2^kOrientQ to its nearest bin and 0 to the next.
struct RowBins {
	uint16x8_t m, bin, f, g;
};

inline RowBins rowBins(const uint16_t *mrow, const uint16_t *orow, int nOrients, bool interpolate)
{
	const uint16x8_t o = vld1q_u16(orow);
	const uint16x8_t one = vdupq_n_u16(1 << kOrientQ);
	RowBins r;
	r.m = vld1q_u16(mrow);
	if (interpolate) {
		r.bin = vshrq_n_u16(o, kOrientQ);
		r.f = vandq_u16(o, vdupq_n_u16((1 << kOrientQ) - 1));
		r.g = vsubq_u16(one, r.f);
	} else {
		// (o + 2^(kOrientQ-1)) >> kOrientQ, the last bin's upper half wrapping to bin 0.
		const uint16x8_t nearest = vrshrq_n_u16(o, kOrientQ);
		r.bin = vbicq_u16(nearest, vcgeq_u16(nearest, vdupq_n_u16(uint16_t(nOrients))));
		r.f = vdupq_n_u16(0);
		r.g = one;
	}
	return r;
}

} // namespace

void shrink4_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	const int w4 = width / 4, h4 = height / 4;
	const int shift = 4 + extraShift;
	const int32x4_t right = vdupq_n_s32(-shift);
	for (int cy = 0; cy < h4; cy++) {
		const uint16_t *row = src + 4 * cy * srcStride;
		uint16_t *out = dst + cy * dstStride;
		int cx = 0;
		for (; cx + 4 <= w4; cx += 4) {
			// Pairs of neighbours summed down the cell's four rows, then pairs of pairs.
			uint32x4_t a = vdupq_n_u32(0), b = vdupq_n_u32(0);
			for (int dy = 0; dy < 4; dy++) {
				const uint16_t *p = row + dy * srcStride + 4 * cx;
				a = vpadalq_u16(a, vld1q_u16(p));
				b = vpadalq_u16(b, vld1q_u16(p + 8));
			}
			vst1_u16(out + cx, vmovn_u32(vrshlq_u32(pairSums(a, b), right)));
		}
		for (; cx < w4; cx++) {
			uint32_t acc = 0;
			for (int dy = 0; dy < 4; dy++) {
				const uint16_t *p = row + dy * srcStride + 4 * cx;
				acc += uint32_t(p[0]) + p[1] + p[2] + p[3];
			}
			out[cx] = static_cast<uint16_t>((acc + (1u << (shift - 1))) >> shift);
		}
	}
}

void gradHist4_neon(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch)
{
	const int w4 = width / 4, h4 = height / 4;
	for (int cy = 0; cy < h4; cy++) {
		const uint16_t *mrow = mag + 4 * cy * stride, *orow = orient + 4 * cy * stride;
		int cx = 0;
		for (; cx + 2 <= w4; cx += 2) {
			RowBins r[4];
			uint16x8_t inPrev[4]; // pixels of bin b - 1 (they give f to bin b)
			for (int dy = 0; dy < 4; dy++) {
				r[dy] = rowBins(mrow + dy * stride + 4 * cx, orow + dy * stride + 4 * cx,
						nOrients, interpolate);
				inPrev[dy] = vceqq_u16(r[dy].bin, vdupq_n_u16(uint16_t(nOrients - 1)));
			}
			for (int b = 0; b < nOrients; b++) {
				uint32x4_t left = vdupq_n_u32(0), right = vdupq_n_u32(0);
				for (int dy = 0; dy < 4; dy++) {
					const uint16x8_t in = vceqq_u16(r[dy].bin, vdupq_n_u16(uint16_t(b)));
					// Added, not or-ed: with one bin, a pixel is in b and b - 1 both.
					const uint16x8_t w = vaddq_u16(vandq_u16(in, r[dy].g),
								       vandq_u16(inPrev[dy], r[dy].f));
					inPrev[dy] = in;
					left = vmlal_u16(left, vget_low_u16(r[dy].m), vget_low_u16(w));
					right = vmlal_u16(right, vget_high_u16(r[dy].m), vget_high_u16(w));
				}
				// (sum + 8 * 2^kOrientQ) >> (4 + kOrientQ), saturated.
				const uint32x2_t sums = laneSums2(left, right);
				const uint16x4_t v = vqrshrn_n_u32(vcombine_u32(sums, sums), 4 + kOrientQ);
				uint16_t *out = hist[b] + cy * histStride + cx;
				vst1_lane_u16(out, v, 0);
				vst1_lane_u16(out + 1, v, 1);
			}
		}
		for (; cx < w4; cx++) {
			histCell(mrow + 4 * cx, orow + 4 * cx, stride, nOrients, interpolate, scratch);
			for (int b = 0; b < nOrients; b++)
				hist[b][cy * histStride + cx] =
					saturateU16((uint64_t(scratch[b]) + (8u << kOrientQ)) >> (4 + kOrientQ));
		}
	}
}

} // namespace kernels
} // namespace calped
