// SPDX-License-Identifier: BSD-2-Clause
// Gradient normalisation M / (S + c) with NEON, four pixels at a time. Bit-identical to
// ref/gradient_ref.cpp's normalizeMag_ref: M * normRcp fits 32 bits (65535 * 41472), and
// the reference's shiftRound by k + 2, which shifts left for small denominators, is the
// saturating rounding shift VQRSHL: a left shift that overflows 32 bits saturates, as the
// reference's 64-bit value saturates to 16 bits.
#include <arm_neon.h>

#include "kernels.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

CALPED_NEON_INLINE uint16x4_t normalize4(const GradientTables &t, uint16x4_t mag, uint32x4_t sum)
{
	const uint32x4_t d = vaddq_u32(sum, vdupq_n_u32(t.normConst));
	const uint32x4_t dZero = vceqq_u32(d, vdupq_n_u32(0));
	// Mantissa m in [2048, 4096) and exponent k of d (a negative k shifts left); for d = 0
	// read entry 0 and discard it.
	const int32x4_t k = vsubq_s32(bitLength4(d), vdupq_n_s32(12));
	const int32x4_t m = vreinterpretq_s32_u32(vshlq_u32(d, vnegq_s32(k)));
	const int32x4_t index = vbslq_s32(dZero, vdupq_n_s32(0), vsubq_s32(m, vdupq_n_s32(2048)));
	const uint32x4_t product = vmulq_u32(vmovl_u16(mag), lookup4(t.normRcp, index));
	const uint32x4_t v = vqrshlq_u32(product, vnegq_s32(vaddq_s32(k, vdupq_n_s32(2))));
	return vqmovn_u32(vbicq_u32(v, dZero));
}

} // namespace

void normalizeMag_neon(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		       const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height)
{
	for (int y = 0; y < height; y++) {
		uint16_t *mrow = mag + y * magStride;
		const uint32_t *srow = smoothedSum + y * sumStride;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			const uint16x8_t m = vld1q_u16(mrow + x);
			const uint16x4_t lo = normalize4(t, vget_low_u16(m), vld1q_u32(srow + x));
			const uint16x4_t hi = normalize4(t, vget_high_u16(m), vld1q_u32(srow + x + 4));
			vst1q_u16(mrow + x, vcombine_u16(lo, hi));
		}
		if (x < width)
			normalizeMag_ref(t, mrow + x, magStride, srow + x, sumStride, width - x, 1);
	}
}

} // namespace kernels
} // namespace calped
