// SPDX-License-Identifier: BSD-2-Clause
// Camera pixel formats -> RGB8 with NEON, sixteen pixels at a time; bit-identical to
// ref/convert_ref.cpp. YUV: the reference's int32 sums, an arithmetic shift (floor) and
// the clamp to 0..255 by saturating narrows; the even and odd pixels of a group are
// computed apart (they share chroma) and interleaved at the end. BGR8 and Gray8 are
// structure loads and stores. Bayer: every neighbour average for all sixteen pixels,
// each channel picked per site. Pixels after the last whole group go through the scalar
// opt code (opt/convert_body.h).
#include <arm_neon.h>

#include "arm/neon_util.h"
#include "opt/convert_body.h"

namespace calped {
namespace kernels {

namespace {

struct YuvConstsNeon {
	int32x4_t bias; // 128 - y * yOffset
	int16_t y, rv, gu, gv, bu;
	explicit YuvConstsNeon(const YuvCoeffs &c)
		: bias(vdupq_n_s32(128 - c.y * c.yOffset)), y(int16_t(c.y)), rv(int16_t(c.rv)),
		  gu(int16_t(c.gu)), gv(int16_t(c.gv)), bu(int16_t(c.bu))
	{
	}
};

// Chroma terms of eight U, V pairs as int32 (low and high four).
struct ChromaNeon {
	int32x4_t r[2], g[2], b[2];
};

CALPED_NEON_INLINE ChromaNeon chroma8(const YuvConstsNeon &k, uint8x8_t u, uint8x8_t v)
{
	const int16x8_t d = vsubq_s16(vreinterpretq_s16_u16(vmovl_u8(u)), vdupq_n_s16(128));
	const int16x8_t e = vsubq_s16(vreinterpretq_s16_u16(vmovl_u8(v)), vdupq_n_s16(128));
	ChromaNeon c;
	const int16x4_t dh[2] = { vget_low_s16(d), vget_high_s16(d) };
	const int16x4_t eh[2] = { vget_low_s16(e), vget_high_s16(e) };
	for (int i = 0; i < 2; i++) {
		c.r[i] = vmull_n_s16(eh[i], k.rv);
		c.g[i] = vmlsl_n_s16(vmull_n_s16(dh[i], int16_t(-k.gu)), eh[i], k.gv);
		c.b[i] = vmull_n_s16(dh[i], k.bu);
	}
	return c;
}

// clamp((y * Y + bias + term) >> 8) for eight luma samples sharing eight chroma terms.
CALPED_NEON_INLINE uint8x8_t channel8(const int32x4_t luma[2], const int32x4_t term[2])
{
	const int16x4_t lo = vqmovn_s32(vshrq_n_s32(vaddq_s32(luma[0], term[0]), 8));
	const int16x4_t hi = vqmovn_s32(vshrq_n_s32(vaddq_s32(luma[1], term[1]), 8));
	return vqmovun_s16(vcombine_s16(lo, hi));
}

// Sixteen pixels: even and odd luma samples (eight each), one chroma pair per two pixels.
CALPED_NEON_INLINE void yuv16(const YuvConstsNeon &k, uint8x8_t yEven, uint8x8_t yOdd,
			      const ChromaNeon &c, uint8_t *d)
{
	int32x4_t even[2], odd[2];
	const int16x8_t ye = vreinterpretq_s16_u16(vmovl_u8(yEven));
	const int16x8_t yo = vreinterpretq_s16_u16(vmovl_u8(yOdd));
	even[0] = vmlal_n_s16(k.bias, vget_low_s16(ye), k.y);
	even[1] = vmlal_n_s16(k.bias, vget_high_s16(ye), k.y);
	odd[0] = vmlal_n_s16(k.bias, vget_low_s16(yo), k.y);
	odd[1] = vmlal_n_s16(k.bias, vget_high_s16(yo), k.y);
	const uint8x8x2_t r = vzip_u8(channel8(even, c.r), channel8(odd, c.r));
	const uint8x8x2_t g = vzip_u8(channel8(even, c.g), channel8(odd, c.g));
	const uint8x8x2_t b = vzip_u8(channel8(even, c.b), channel8(odd, c.b));
	uint8x16x3_t rgb;
	rgb.val[0] = vcombine_u8(r.val[0], r.val[1]);
	rgb.val[1] = vcombine_u8(g.val[0], g.val[1]);
	rgb.val[2] = vcombine_u8(b.val[0], b.val[1]);
	vst3q_u8(d, rgb);
}

} // namespace

void yuv420ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const YuvConstsNeon k(f.yuv);
	const int step = f.chromaStep;
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *luma = f.planes[0] + y * f.strides[0];
		const uint8_t *u = f.planes[1] + (y / 2) * f.strides[1];
		const uint8_t *v = f.planes[2] + (y / 2) * f.strides[2];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		if (step == 1 || step == 2) {
			// x + 16 < width: with step 2 the loads reach one byte past the group's last
			// chroma sample, which pixel x + 16's sample bounds.
			for (; x + 16 < f.width; x += 16) {
				const uint8x8x2_t l = vld2_u8(luma + x);
				uint8x8_t us, vs;
				if (step == 1) {
					us = vld1_u8(u + x / 2);
					vs = vld1_u8(v + x / 2);
				} else {
					us = vld2_u8(u + x).val[0];
					vs = vld2_u8(v + x).val[0];
				}
				yuv16(k, l.val[0], l.val[1], chroma8(k, us, vs), d + 3 * x);
			}
		}
		yuv420RowTail(f.yuv, luma, u, v, step, x, f.width, d);
	}
}

void yuyvToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const YuvConstsNeon k(f.yuv);
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		for (; x + 16 <= f.width; x += 16) {
			const uint8x8x4_t q = vld4_u8(s + 2 * x); // Y0 U Y1 V, eight pairs
			yuv16(k, q.val[0], q.val[2], chroma8(k, q.val[1], q.val[3]), d + 3 * x);
		}
		yuyvRowTail(f.yuv, s, x, f.width, d);
	}
}

void bgr8ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		for (; x + 16 <= f.width; x += 16) {
			uint8x16x3_t p = vld3q_u8(s + 3 * x);
			const uint8x16_t blue = p.val[0];
			p.val[0] = p.val[2];
			p.val[2] = blue;
			vst3q_u8(d + 3 * x, p);
		}
		for (; x < f.width; x++) {
			d[3 * x + 0] = s[3 * x + 2];
			d[3 * x + 1] = s[3 * x + 1];
			d[3 * x + 2] = s[3 * x + 0];
		}
	}
}

void gray8ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		for (; x + 16 <= f.width; x += 16) {
			const uint8x16_t g = vld1q_u8(s + x);
			uint8x16x3_t p;
			p.val[0] = p.val[1] = p.val[2] = g;
			vst3q_u8(d + 3 * x, p);
		}
		for (; x < f.width; x++)
			d[3 * x + 0] = d[3 * x + 1] = d[3 * x + 2] = s[x];
	}
}

namespace {

// The neighbour averages of sixteen pixels at columns x .. x + 15 (bayerToRgb8_ref).
struct BayerValues {
	uint8x16_t here, cross, diagonal, across, vertical;
};

template <Site site>
CALPED_NEON_INLINE uint8x16_t pick(const BayerValues &v, int channel)
{
	switch (site) {
	case RedSite:
		return channel == 0 ? v.here : channel == 1 ? v.cross : v.diagonal;
	case BlueSite:
		return channel == 0 ? v.diagonal : channel == 1 ? v.cross : v.here;
	case GreenInRedRow:
		return channel == 0 ? v.across : channel == 1 ? v.here : v.vertical;
	default: // GreenInBlueRow
		return channel == 0 ? v.vertical : channel == 1 ? v.here : v.across;
	}
}

// (a + b + c + d + 2) >> 2 of sixteen byte lanes.
CALPED_NEON_INLINE uint8x16_t average4(uint8x16_t a, uint8x16_t b, uint8x16_t c, uint8x16_t d)
{
	const uint16x8_t lo = vaddq_u16(vaddl_u8(vget_low_u8(a), vget_low_u8(b)),
					vaddl_u8(vget_low_u8(c), vget_low_u8(d)));
	const uint16x8_t hi = vaddq_u16(vaddl_u8(vget_high_u8(a), vget_high_u8(b)),
					vaddl_u8(vget_high_u8(c), vget_high_u8(d)));
	return vcombine_u8(vrshrn_n_u16(lo, 2), vrshrn_n_u16(hi, 2));
}

template <Site even, Site odd>
void demosaicRowNeon(const uint8_t *u, const uint8_t *c, const uint8_t *b, int w, uint8_t *d)
{
	// Column 0 mirrors its left neighbour to column 1; columns from 1 on in groups of
	// sixteen while their right neighbours exist; the rest (and the mirrored last
	// column) scalar.
	demosaic<even>(u, c, b, 1, 0, 1, d);
	// Lanes 0, 2, ... are odd columns (groups start at odd x).
	static const uint8_t kOddLane[16] = { 255, 0, 255, 0, 255, 0, 255, 0,
					      255, 0, 255, 0, 255, 0, 255, 0 };
	const uint8x16_t oddLane = vld1q_u8(kOddLane);
	int x = 1;
	for (; x + 17 <= w; x += 16) {
		const uint8x16_t cl = vld1q_u8(c + x - 1), cx = vld1q_u8(c + x), cr = vld1q_u8(c + x + 1);
		const uint8x16_t ul = vld1q_u8(u + x - 1), ux = vld1q_u8(u + x), ur = vld1q_u8(u + x + 1);
		const uint8x16_t bl = vld1q_u8(b + x - 1), bx = vld1q_u8(b + x), br = vld1q_u8(b + x + 1);
		BayerValues v;
		v.here = cx;
		v.cross = average4(cl, cr, ux, bx);
		v.diagonal = average4(ul, ur, bl, br);
		v.across = vrhaddq_u8(cl, cr);   // (l + r + 1) >> 1
		v.vertical = vrhaddq_u8(ux, bx); // (u + b + 1) >> 1
		uint8x16x3_t rgb;
		rgb.val[0] = vbslq_u8(oddLane, pick<odd>(v, 0), pick<even>(v, 0));
		rgb.val[1] = vbslq_u8(oddLane, pick<odd>(v, 1), pick<even>(v, 1));
		rgb.val[2] = vbslq_u8(oddLane, pick<odd>(v, 2), pick<even>(v, 2));
		vst3q_u8(d + 3 * x, rgb);
	}
	demosaicTail<even, odd>(u, c, b, x, w, d);
}

} // namespace

void bayerToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const int w = f.width, h = f.height;
	for (int y = y0; y < y0 + rows; y++) {
		const int above = y > 0 ? y - 1 : 1, below = y + 1 < h ? y + 1 : h - 2;
		const uint8_t *u = f.planes[0] + above * f.strides[0];
		const uint8_t *c = f.planes[0] + y * f.strides[0];
		const uint8_t *b = f.planes[0] + below * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		const bool redRow = (y & 1) == f.redY;
		if (redRow && f.redX == 0)
			demosaicRowNeon<RedSite, GreenInRedRow>(u, c, b, w, d);
		else if (redRow)
			demosaicRowNeon<GreenInRedRow, RedSite>(u, c, b, w, d);
		else if (f.redX == 0)
			demosaicRowNeon<GreenInBlueRow, BlueSite>(u, c, b, w, d);
		else
			demosaicRowNeon<BlueSite, GreenInBlueRow>(u, c, b, w, d);
	}
}

} // namespace kernels
} // namespace calped
