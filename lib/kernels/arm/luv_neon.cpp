// SPDX-License-Identifier: BSD-2-Clause
// RGB8 -> LUV (Q16) with NEON, eight pixels at a time. Bit-identical to ref/luv_ref.cpp:
// the reference's 64-bit products are widening multiplies, its shiftRound the rounding
// shifts (VRSHL adds 2^(s-1) before shifting, as shiftRound does); the L and reciprocal
// tables are read lane by lane.
#include <arm_neon.h>

#include "kernels.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

inline int32x4_t dot3(const int32_t c[3], int32x4_t r, int32x4_t g, int32x4_t b)
{
	return vmlaq_n_s32(vmlaq_n_s32(vmulq_n_s32(r, c[0]), g, c[1]), b, c[2]);
}

// shiftRound(a * b, s) per lane (s in 1..63 per lane), for results that fit 32 bits.
inline int32x4_t mulShiftRound(int32x4_t a, int32x4_t b, int32x4_t s)
{
	const int64x2_t negLo = vmovl_s32(vneg_s32(vget_low_s32(s)));
	const int64x2_t negHi = vmovl_s32(vneg_s32(vget_high_s32(s)));
	const int64x2_t lo = vrshlq_s64(vmull_s32(vget_low_s32(a), vget_low_s32(b)), negLo);
	const int64x2_t hi = vrshlq_s64(vmull_s32(vget_high_s32(a), vget_high_s32(b)), negHi);
	return vcombine_s32(vmovn_s64(lo), vmovn_s64(hi));
}

// shiftRound(a * b, kLuvRatioQ) per lane, for results that fit 32 bits.
inline int32x4_t mulShiftRoundRatio(int32x4_t a, int32x4_t b)
{
	const int64x2_t lo = vrshrq_n_s64(vmull_s32(vget_low_s32(a), vget_low_s32(b)), kLuvRatioQ);
	const int64x2_t hi = vrshrq_n_s64(vmull_s32(vget_high_s32(a), vget_high_s32(b)), kLuvRatioQ);
	return vcombine_s32(vmovn_s64(lo), vmovn_s64(hi));
}

struct Luv4 {
	uint16x4_t l, u, v;
};

CALPED_NEON_INLINE Luv4 luv4(const LuvTables &t, uint16x4_t r16, uint16x4_t g16,
			     uint16x4_t b16)
{
	const int32x4_t r = vreinterpretq_s32_u32(vmovl_u16(r16));
	const int32x4_t g = vreinterpretq_s32_u32(vmovl_u16(g16));
	const int32x4_t b = vreinterpretq_s32_u32(vmovl_u16(b16));
	const int32x4_t X = dot3(t.cx, r, g, b), Y = dot3(t.cy, r, g, b), Z = dot3(t.cz, r, g, b);
	const int32x4_t L = vreinterpretq_s32_u32(lookup4(t.l, vshrq_n_s32(Y, 18)));
	const int32x4_t d = vaddq_s32(vmlaq_n_s32(vshrq_n_s32(X, 2), vshrq_n_s32(Y, 2), 15),
				      vmulq_n_s32(vshrq_n_s32(Z, 2), 3));
	const uint32x4_t dZero = vceqq_s32(d, vdupq_n_s32(0));

	// Mantissa m in [4096, 8192) and exponent k of d: m = d >> k, or d << -k for k < 0
	// (a negative count shifts the other way). For d = 0, read entry 0 and discard it.
	const int32x4_t k = vsubq_s32(bitLength4(vreinterpretq_u32_s32(d)), vdupq_n_s32(13));
	const int32x4_t m = vreinterpretq_s32_u32(vshlq_u32(vreinterpretq_u32_s32(d), vnegq_s32(k)));
	const int32x4_t index = vbslq_s32(dZero, vdupq_n_s32(0), vsubq_s32(m, vdupq_n_s32(4096)));
	const int32x4_t rcp = vreinterpretq_s32_u32(lookup4(t.rcp, index));
	const int32x4_t shift = vaddq_s32(k, vdupq_n_s32(30 - kLuvRatioQ));
	const int32x4_t notZero = vreinterpretq_s32_u32(vmvnq_u32(dZero));
	const int32x4_t xd = vandq_s32(mulShiftRound(X, rcp, shift), notZero);
	const int32x4_t yd = vandq_s32(mulShiftRound(Y, rcp, shift), notZero);

	const int32x4_t tu = vsubq_s32(vmulq_n_s32(xd, 52), vdupq_n_s32(t.un13));
	const int32x4_t tv = vsubq_s32(vmulq_n_s32(yd, 117), vdupq_n_s32(t.vn13));
	const int32x4_t U = vsubq_s32(mulShiftRoundRatio(L, tu), vdupq_n_s32(t.minu));
	const int32x4_t V = vsubq_s32(mulShiftRoundRatio(L, tv), vdupq_n_s32(t.minv));
	return { vmovn_u32(vreinterpretq_u32_s32(L)), vqmovun_s32(U), vqmovun_s32(V) };
}

} // namespace

void rgbToLuv_neon(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		   int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride)
{
	for (int y = 0; y < height; y++) {
		const uint8_t *p = rgb + y * rgbStride;
		uint16_t *lo = l + y * stride, *uo = u + y * stride, *vo = v + y * stride;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			const uint8x8x3_t px = vld3_u8(p + 3 * x); // de-interleaves R, G, B
			const uint16x8_t r = vmovl_u8(px.val[0]), g = vmovl_u8(px.val[1]),
					 b = vmovl_u8(px.val[2]);
			const Luv4 a = luv4(t, vget_low_u16(r), vget_low_u16(g), vget_low_u16(b));
			const Luv4 c = luv4(t, vget_high_u16(r), vget_high_u16(g), vget_high_u16(b));
			vst1q_u16(lo + x, vcombine_u16(a.l, c.l));
			vst1q_u16(uo + x, vcombine_u16(a.u, c.u));
			vst1q_u16(vo + x, vcombine_u16(a.v, c.v));
		}
		if (x < width)
			rgbToLuv_ref(t, p + 3 * x, rgbStride, width - x, 1, lo + x, uo + x, vo + x, stride);
	}
}

} // namespace kernels
} // namespace calped
