// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation with NEON: the derivative rows as in the portable
// build (gradient_rows.h, which the compiler vectorises), the per-pixel part here four
// pixels at a time with the table reads lane by lane. Bit-identical to
// ref/gradient_ref.cpp: as in the AVX2 build, the reference's 64-bit
// shiftRound(gx * rsqrt, 8 + k/2) is computed as shiftRound((gx << (10 - k/2)) * rsqrt, 18),
// the same integer, which fits 32 bits because |gx| <= sqrt(m2).
#include <arm_neon.h>

#include <cstddef>

#include "opt/gradient_rows.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

// The three orientation tables are read through one base pointer.
static_assert(offsetof(GradientTables, fromSinAcute) ==
		      offsetof(GradientTables, fromCos) + sizeof(uint16_t) * (2 * 4096 + 1),
	      "orientation tables are contiguous");
static_assert(offsetof(GradientTables, fromSinObtuse) ==
		      offsetof(GradientTables, fromSinAcute) + sizeof(uint16_t) * (4096 + 1),
	      "orientation tables are contiguous");

// Magnitude and orientation of four pixels. m2 = 0 needs no special case: its mantissa
// is 0, sqrtQ8[0] = rsqrtQ20[0] = 0, so the magnitude is 0 and c12 = 0 reads fromCos[4096],
// the reference's orientation for no gradient.
void gradientPixels4(const GradientTables &t, const int32_t *gxp, const int32_t *gyp,
		     uint16x4_t &mag, uint16x4_t &orient)
{
	const int32x4_t gx = vld1q_s32(gxp), gy = vld1q_s32(gyp);
	const uint32x4_t m2 = vreinterpretq_u32_s32(vmlaq_s32(vmulq_s32(gx, gx), gy, gy));

	// k = bitLength - 12, at least 0, rounded up to even; m = m2 >> k.
	int32x4_t k = vmaxq_s32(vsubq_s32(bitLength4(m2), vdupq_n_s32(12)), vdupq_n_s32(0));
	k = vaddq_s32(k, vandq_s32(k, vdupq_n_s32(1)));
	const int32x4_t m = vreinterpretq_s32_u32(vshlq_u32(m2, vnegq_s32(k)));
	const int32x4_t halfK = vshrq_n_s32(k, 1);

	// |G| = shiftRound(sqrtQ8[m] << k/2, 9), below 2^15.
	const uint32x4_t sq = vshlq_u32(lookup4(t.sqrtQ8, m), halfK);
	mag = vrshrn_n_u32(sq, 9);

	// cos and sin in Q12 of the orientation folded into [0, pi).
	const int32x4_t rs = vreinterpretq_s32_u32(lookup4(t.rsqrtQ20, m));
	const uint32x4_t gyNeg = vcltq_s32(gy, vdupq_n_s32(0));
	const int32x4_t gxf = vbslq_s32(gyNeg, vnegq_s32(gx), gx);
	const int32x4_t up = vsubq_s32(vdupq_n_s32(10), halfK);
	int32x4_t c12 = vrshrq_n_s32(vmulq_s32(vshlq_s32(gxf, up), rs), 18);
	c12 = vmaxq_s32(vminq_s32(c12, vdupq_n_s32(4096)), vdupq_n_s32(-4096));
	int32x4_t s12 = vrshrq_n_s32(vmulq_s32(vshlq_s32(vabsq_s32(gy), up), rs), 18);
	s12 = vminq_s32(s12, vdupq_n_s32(4096));

	// acos is ill-conditioned near 0 and pi: asin there. Index into fromCos, fromSinAcute
	// and fromSinObtuse laid end to end.
	const uint32x4_t useCos = vandq_u32(vcgeq_s32(c12, vdupq_n_s32(-2896)),
					    vcleq_s32(c12, vdupq_n_s32(2896)));
	const int32x4_t sinBase = vbslq_s32(vcgtq_s32(c12, vdupq_n_s32(0)), vdupq_n_s32(8193),
					    vdupq_n_s32(8193 + 4097));
	const int32x4_t index =
		vbslq_s32(useCos, vaddq_s32(c12, vdupq_n_s32(4096)), vaddq_s32(sinBase, s12));
	orient = vmovn_u32(lookup4(t.fromCos, index));
}

} // namespace

void gradMagOrient_neon(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *scratch)
{
	int32_t *bx = scratch, *by = bx + width, *cx = by + width, *cy = cx + width;
	for (int y = 0; y < height; y++) {
		strongestGradientRow(planes, stride, width, height, y, bx, by, cx, cy);
		uint16_t *mo = mag + y * outStride;
		uint16_t *oo = orient + y * outStride;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			uint16x4_t m0, o0, m1, o1;
			gradientPixels4(t, bx + x, by + x, m0, o0);
			gradientPixels4(t, bx + x + 4, by + x + 4, m1, o1);
			vst1q_u16(mo + x, vcombine_u16(m0, m1));
			vst1q_u16(oo + x, vcombine_u16(o0, o1));
		}
		for (; x < width; x++)
			gradientPixel(t, bx[x], by[x], mo + x, oo + x);
	}
}

} // namespace kernels
} // namespace calped
