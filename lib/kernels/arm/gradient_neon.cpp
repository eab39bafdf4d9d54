// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation with NEON, eight pixels at a time in one pass:
// derivatives of the three channels, the strongest kept, then magnitude and orientation
// with the table reads lane by lane (the row's first and last pixel take the scalar path;
// the inner pixels after the last whole block are one more block, overlapping).
// Bit-identical to ref/gradient_ref.cpp: as in the AVX2 build, the reference's cosine
// gx * rsqrt * 2^-(20 + k/2) is formed as (gx << (10 - k/2)) * rsqrt = cos * 2^30, which
// fits 32 bits because |gx| <= sqrt(m2), and multiplied by 10000 in widening multiplies.
#include <arm_neon.h>

#include <cstddef>

#include "opt/gradient_rows.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

// Magnitude and orientation of four pixels from their doubled derivatives and m2, the
// squared magnitude. m2 = 0 needs no special case: its mantissa is 0 and
// sqrtQ8[0] = rsqrtQ20[0] = 0, so the magnitude is 0 and the cosine 0 reads
// fromCos[kCosSteps], the reference's orientation for no gradient.
CALPED_NEON_INLINE void gradientPixels4(const GradientTables &t, int32x4_t gx, int32x4_t gy,
					uint32x4_t m2, uint16x4_t &mag, uint16x4_t &orient)
{
	// k = bitLength - 12, at least 0, rounded up to even; m = m2 >> k.
	int32x4_t k = vmaxq_s32(vsubq_s32(bitLength4(m2), vdupq_n_s32(12)), vdupq_n_s32(0));
	k = vaddq_s32(k, vandq_s32(k, vdupq_n_s32(1)));
	const int32x4_t m = vreinterpretq_s32_u32(vshlq_u32(m2, vnegq_s32(k)));
	const int32x4_t halfK = vshrq_n_s32(k, 1);

	// Both roots of each lane's m in one read: rsqrtQ20 in val[0], sqrtQ8 in val[1].
	const uint32x4x2_t roots = lookupPairs4(t.roots, m);
	// |G| = shiftRound(sqrtQ8[m] << k/2, 9), below 2^15.
	const uint32x4_t sq = vshlq_u32(roots.val[1], halfK);
	mag = vrshrn_n_u32(sq, 9);

	// cos * 2^30 of the orientation folded into [0, pi), then the toolbox's acos index
	// trunc(cos * 10000).
	const int32x4_t rs = vreinterpretq_s32_u32(roots.val[0]);
	const uint32x4_t gyNeg = vcltq_s32(gy, vdupq_n_s32(0));
	const int32x4_t gxf = vbslq_s32(gyNeg, vnegq_s32(gx), gx);
	const int32x4_t up = vsubq_s32(vdupq_n_s32(10), halfK);
	const int32x4_t p = vmulq_s32(vshlq_s32(gxf, up), rs);
	const uint32x4_t absP = vreinterpretq_u32_s32(vabsq_s32(p));
	const uint32x2_t steps = vdup_n_u32(kCosSteps);
	const uint32x4_t c = vminq_u32(
		vcombine_u32(vshrn_n_u64(vmull_u32(vget_low_u32(absP), steps), 30),
			     vshrn_n_u64(vmull_u32(vget_high_u32(absP), steps), 30)),
		vdupq_n_u32(kCosSteps));
	const int32x4_t cs = vreinterpretq_s32_u32(c);
	const int32x4_t index =
		vaddq_s32(vbslq_s32(vcltq_s32(p, vdupq_n_s32(0)), vnegq_s32(cs), cs), vdupq_n_s32(kCosSteps));
	orient = vmovn_u32(lookup4(t.fromCos, index));
}

inline int32x4_t clampDiff4(int32x4_t v)
{
	return vmaxq_s32(vminq_s32(v, vdupq_n_s32(46340)), vdupq_n_s32(-46340));
}

// The strongest channel's doubled derivatives at four inner pixels (0 < x, x + 4 < width):
// b - a and scale * (d - c) from the four-sample rows a, b (left and right neighbours) and
// c, d (above and below).
struct Gradient4 {
	int32x4_t gx, gy;
	uint32x4_t m2;
};

inline Gradient4 channelGradient4(uint16x4_t left, uint16x4_t right, uint16x4_t above,
				  uint16x4_t below, int vScale)
{
	Gradient4 g;
	g.gx = clampDiff4(vreinterpretq_s32_u32(vsubl_u16(right, left)));
	g.gy = clampDiff4(vmulq_n_s32(vreinterpretq_s32_u32(vsubl_u16(below, above)), vScale));
	g.m2 = vreinterpretq_u32_s32(vmlaq_s32(vmulq_s32(g.gx, g.gx), g.gy, g.gy));
	return g;
}

// Keep the channel with the larger squared magnitude (the earlier on ties).
inline void keepStronger(Gradient4 &best, const Gradient4 &g)
{
	const uint32x4_t take = vcgtq_u32(g.m2, best.m2);
	best.gx = vbslq_s32(take, g.gx, best.gx);
	best.gy = vbslq_s32(take, g.gy, best.gy);
	best.m2 = vbslq_u32(take, g.m2, best.m2);
}

// Eight inner pixels of row y starting at x: derivatives of the three channels, the
// strongest kept, then magnitude and orientation.
CALPED_NEON_INLINE void gradientPixels8(const GradientTables &t, const uint16_t *const rows[3][3],
					int x, int vScale, uint16_t *mag, uint16_t *orient)
{
	Gradient4 lo, hi;
	for (int c = 0; c < 3; c++) {
		const uint16_t *above = rows[c][0] + x, *row = rows[c][1] + x, *below = rows[c][2] + x;
		const uint16x8_t l = vld1q_u16(row - 1), r = vld1q_u16(row + 1);
		const uint16x8_t a = vld1q_u16(above), b = vld1q_u16(below);
		const Gradient4 gl = channelGradient4(vget_low_u16(l), vget_low_u16(r), vget_low_u16(a),
						      vget_low_u16(b), vScale);
		const Gradient4 gh = channelGradient4(vget_high_u16(l), vget_high_u16(r),
						      vget_high_u16(a), vget_high_u16(b), vScale);
		if (c == 0) {
			lo = gl;
			hi = gh;
		} else {
			keepStronger(lo, gl);
			keepStronger(hi, gh);
		}
	}
	uint16x4_t m0, o0, m1, o1;
	gradientPixels4(t, lo.gx, lo.gy, lo.m2, m0, o0);
	gradientPixels4(t, hi.gx, hi.gy, hi.m2, m1, o1);
	vst1q_u16(mag, vcombine_u16(m0, m1));
	vst1q_u16(orient, vcombine_u16(o0, o1));
}

// One pixel the scalar way (the row ends): the reference's derivatives and channel choice.
void gradientPixel1(const GradientTables &t, const uint16_t *const rows[3][3], int x, int width,
		    int vScale, uint16_t *mag, uint16_t *orient)
{
	int32_t bx = 0, by = 0;
	uint32_t best = 0;
	for (int c = 0; c < 3; c++) {
		const uint16_t *row = rows[c][1];
		int32_t gx = 0;
		if (width > 1) {
			if (x == 0)
				gx = 2 * (int32_t(row[1]) - int32_t(row[0]));
			else if (x == width - 1)
				gx = 2 * (int32_t(row[x]) - int32_t(row[x - 1]));
			else
				gx = int32_t(row[x + 1]) - int32_t(row[x - 1]);
		}
		gx = clampDiff(gx);
		const int32_t gy = clampDiff(vScale * (int32_t(rows[c][2][x]) - int32_t(rows[c][0][x])));
		const uint32_t m2 = uint32_t(gx * gx) + uint32_t(gy * gy);
		if (c == 0 || m2 > best) {
			best = m2;
			bx = gx;
			by = gy;
		}
	}
	gradientPixel(t, bx, by, mag, orient);
}

} // namespace

void gradMagOrient_neon(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *)
{
	for (int y = 0; y < height; y++) {
		// Vertical differences: rows above and below, one-sided (doubled) at the top and
		// bottom, none for a single row.
		const int up = y > 0 ? y - 1 : y, down = y < height - 1 ? y + 1 : y;
		const int vScale = height < 2 ? 0 : (y == 0 || y == height - 1 ? 2 : 1);
		const uint16_t *rows[3][3];
		for (int c = 0; c < 3; c++) {
			rows[c][0] = planes[c] + up * stride;
			rows[c][1] = planes[c] + y * stride;
			rows[c][2] = planes[c] + down * stride;
		}
		uint16_t *mo = mag + y * outStride;
		uint16_t *oo = orient + y * outStride;
		gradientPixel1(t, rows, 0, width, vScale, mo, oo);
		int x = 1;
		for (; x + 8 < width; x += 8)
			gradientPixels8(t, rows, x, vScale, mo + x, oo + x);
		// The inner pixels left as one more block ending at width - 2, overlapping the
		// one before (the same values written again).
		if (x < width - 1 && width >= 10) {
			gradientPixels8(t, rows, width - 9, vScale, mo + width - 9, oo + width - 9);
			x = width - 1;
		}
		for (; x < width; x++)
			gradientPixel1(t, rows, x, width, vScale, mo + x, oo + x);
	}
}

} // namespace kernels
} // namespace calped
