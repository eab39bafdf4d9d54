// SPDX-License-Identifier: BSD-2-Clause
// YUV -> RGB8 with AVX2, eight pixels at a time; bit-identical to ref/convert_ref.cpp:
// the same int32 sums, an arithmetic shift (floor), and the clamp to 0..255 done by the
// saturating packs (after the shift every value lies within -300..600, inside int16).
// Pixels after the last whole group of eight go through the scalar opt code. BGR8 and
// Gray8 are byte shuffles. Bayer: sixteen pixels at a time in 16-bit lanes, every
// neighbour sum computed for all of them and each channel picked per site.
#include <immintrin.h>

#include <cstring>

#include "opt/convert_body.h"

namespace calped {
namespace kernels {

namespace {

struct YuvConsts {
	__m256i y, bias, c128, rv, gu, gv, bu;
	explicit YuvConsts(const YuvCoeffs &c)
		: y(_mm256_set1_epi32(c.y)), bias(_mm256_set1_epi32(128 - c.y * c.yOffset)),
		  c128(_mm256_set1_epi32(128)), rv(_mm256_set1_epi32(c.rv)),
		  gu(_mm256_set1_epi32(c.gu)), gv(_mm256_set1_epi32(c.gv)), bu(_mm256_set1_epi32(c.bu))
	{
	}
};

// Unaligned loads of 8 and 4 bytes into the low end of a register.
inline __m128i load8(const uint8_t *p) { return _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p)); }
inline __m128i load4(const uint8_t *p)
{
	int32_t v;
	std::memcpy(&v, p, 4);
	return _mm_cvtsi32_si128(v);
}

// Eight int32 lanes -> eight saturated int16 in a 128-bit register.
inline __m128i narrow(__m256i v)
{
	return _mm_packs_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
}

// Eight pixels: y8 holds their luma (low 8 bytes), uv8 the four chroma pairs they share
// as u0 v0 u1 v1 u2 v2 u3 v3; 24 bytes of RGB go to out.
inline void yuv8(const YuvConsts &k, __m128i y8, __m128i uv8, uint8_t *out)
{
	const __m256i luma = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvtepu8_epi32(y8), k.y), k.bias);
	// Lanes u0 v0 u1 v1 | u2 v2 u3 v3: each half duplicates its pairs for its 4 pixels.
	const __m256i uv = _mm256_sub_epi32(_mm256_cvtepu8_epi32(uv8), k.c128);
	const __m256i d = _mm256_shuffle_epi32(uv, _MM_SHUFFLE(2, 2, 0, 0));
	const __m256i e = _mm256_shuffle_epi32(uv, _MM_SHUFFLE(3, 3, 1, 1));
	const __m256i r = _mm256_srai_epi32(_mm256_add_epi32(luma, _mm256_mullo_epi32(k.rv, e)), 8);
	const __m256i g = _mm256_srai_epi32(
		_mm256_sub_epi32(_mm256_sub_epi32(luma, _mm256_mullo_epi32(k.gu, d)),
				 _mm256_mullo_epi32(k.gv, e)), 8);
	const __m256i b = _mm256_srai_epi32(_mm256_add_epi32(luma, _mm256_mullo_epi32(k.bu, d)), 8);
	const __m128i rg = _mm_packus_epi16(narrow(r), narrow(g)); // r0..r7 g0..g7
	const __m128i b16 = narrow(b);
	const __m128i bb = _mm_packus_epi16(b16, b16); // b0..b7 twice
	const __m128i rg0 = _mm_setr_epi8(0, 8, -1, 1, 9, -1, 2, 10, -1, 3, 11, -1, 4, 12, -1, 5);
	const __m128i b0 = _mm_setr_epi8(-1, -1, 0, -1, -1, 1, -1, -1, 2, -1, -1, 3, -1, -1, 4, -1);
	const __m128i rg1 = _mm_setr_epi8(13, -1, 6, 14, -1, 7, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1);
	const __m128i b1 = _mm_setr_epi8(-1, 5, -1, -1, 6, -1, -1, 7, -1, -1, -1, -1, -1, -1, -1, -1);
	const __m128i first = _mm_or_si128(_mm_shuffle_epi8(rg, rg0), _mm_shuffle_epi8(bb, b0));
	const __m128i rest = _mm_or_si128(_mm_shuffle_epi8(rg, rg1), _mm_shuffle_epi8(bb, b1));
	_mm_storeu_si128(reinterpret_cast<__m128i *>(out), first);
	_mm_storel_epi64(reinterpret_cast<__m128i *>(out + 16), rest);
}

} // namespace

void yuv420ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const YuvConsts k(f.yuv);
	const int groups = f.width / 8 * 8;
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *luma = f.planes[0] + y * f.strides[0];
		const uint8_t *u = f.planes[1] + (y / 2) * f.strides[1];
		const uint8_t *v = f.planes[2] + (y / 2) * f.strides[2];
		uint8_t *d = dst + (y - y0) * dstStride;
		if (f.chromaStep == 2) // NV12: the 8 bytes at u + x are the 4 pairs, in order
			for (int x = 0; x < groups; x += 8)
				yuv8(k, load8(luma + x), load8(u + x), d + 3 * x);
		else
			for (int x = 0; x < groups; x += 8)
				yuv8(k, load8(luma + x), _mm_unpacklo_epi8(load4(u + x / 2), load4(v + x / 2)),
				     d + 3 * x);
		yuv420RowTail(f.yuv, luma, u, v, f.chromaStep, groups, f.width, d);
	}
}

void yuyvToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const YuvConsts k(f.yuv);
	const int groups = f.width / 8 * 8;
	const __m128i lumaBytes = _mm_setr_epi8(0, 2, 4, 6, 8, 10, 12, 14, -1, -1, -1, -1, -1, -1, -1, -1);
	const __m128i chromaBytes = _mm_setr_epi8(1, 3, 5, 7, 9, 11, 13, 15, -1, -1, -1, -1, -1, -1, -1, -1);
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		for (int x = 0; x < groups; x += 8) {
			const __m128i q = _mm_loadu_si128(reinterpret_cast<const __m128i *>(s + 2 * x));
			yuv8(k, _mm_shuffle_epi8(q, lumaBytes), _mm_shuffle_epi8(q, chromaBytes), d + 3 * x);
		}
		yuyvRowTail(f.yuv, s, groups, f.width, d);
	}
}

void bgr8ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	// Four pixels per 16-byte load; the four bytes after them are stored too and
	// rewritten by the next step, so the loop stops while 16 bytes remain in the row.
	const __m128i swap = _mm_setr_epi8(2, 1, 0, 5, 4, 3, 8, 7, 6, 11, 10, 9, 12, 13, 14, 15);
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		for (; 3 * x + 16 <= 3 * f.width; x += 4) {
			const __m128i q = _mm_loadu_si128(reinterpret_cast<const __m128i *>(s + 3 * x));
			_mm_storeu_si128(reinterpret_cast<__m128i *>(d + 3 * x), _mm_shuffle_epi8(q, swap));
		}
		for (; x < f.width; x++) {
			d[3 * x + 0] = s[3 * x + 2];
			d[3 * x + 1] = s[3 * x + 1];
			d[3 * x + 2] = s[3 * x + 0];
		}
	}
}

void gray8ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	// Sixteen pixels per load, tripled into 48 bytes by three shuffles.
	const __m128i m0 = _mm_setr_epi8(0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5);
	const __m128i m1 = _mm_setr_epi8(5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8, 9, 9, 9, 10, 10);
	const __m128i m2 = _mm_setr_epi8(10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15);
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		int x = 0;
		for (; x + 16 <= f.width; x += 16) {
			const __m128i q = _mm_loadu_si128(reinterpret_cast<const __m128i *>(s + x));
			__m128i *o = reinterpret_cast<__m128i *>(d + 3 * x);
			_mm_storeu_si128(o, _mm_shuffle_epi8(q, m0));
			_mm_storeu_si128(o + 1, _mm_shuffle_epi8(q, m1));
			_mm_storeu_si128(o + 2, _mm_shuffle_epi8(q, m2));
		}
		for (; x < f.width; x++)
			d[3 * x + 0] = d[3 * x + 1] = d[3 * x + 2] = s[x];
	}
}

namespace {

// The channel c (0 R, 1 G, 2 B) of a Bayer site from the neighbour sums (bayerToRgb8_ref).
template <Site site>
inline __m256i siteChannel(int c, __m256i here, __m256i cross, __m256i diagonal, __m256i across,
			   __m256i vertical)
{
	switch (site) {
	case RedSite: return c == 0 ? here : (c == 1 ? cross : diagonal);
	case BlueSite: return c == 0 ? diagonal : (c == 1 ? cross : here);
	case GreenInRedRow: return c == 0 ? across : (c == 1 ? here : vertical);
	default: return c == 0 ? vertical : (c == 1 ? here : across);
	}
}

inline __m256i load16(const uint8_t *p)
{
	return _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)));
}

template <Site even, Site odd>
void demosaicRowAvx2(const uint8_t *u, const uint8_t *c, const uint8_t *b, int w, uint8_t *d)
{
	demosaic<even>(u, c, b, 1, 0, 1, d); // column 0 mirrors column -1 to 1
	// Groups start at odd columns: lane j holds column x + j, even when j is odd.
	const __m256i evenLanes = _mm256_setr_epi16(0, -1, 0, -1, 0, -1, 0, -1, 0, -1, 0, -1, 0, -1, 0, -1);
	const __m256i two = _mm256_set1_epi16(2), one = _mm256_set1_epi16(1);
	const __m128i rg0 = _mm_setr_epi8(0, 8, -1, 1, 9, -1, 2, 10, -1, 3, 11, -1, 4, 12, -1, 5);
	const __m128i b0 = _mm_setr_epi8(-1, -1, 0, -1, -1, 1, -1, -1, 2, -1, -1, 3, -1, -1, 4, -1);
	const __m128i rg1 = _mm_setr_epi8(13, -1, 6, 14, -1, 7, 15, -1, -1, -1, -1, -1, -1, -1, -1, -1);
	const __m128i b1 = _mm_setr_epi8(-1, 5, -1, -1, 6, -1, -1, 7, -1, -1, -1, -1, -1, -1, -1, -1);
	int x = 1;
	for (; x + 17 <= w; x += 16) { // reads columns x - 1 .. x + 16
		const __m256i cl = load16(c + x - 1), here = load16(c + x), cr = load16(c + x + 1);
		const __m256i ul = load16(u + x - 1), ux = load16(u + x), ur = load16(u + x + 1);
		const __m256i bl = load16(b + x - 1), bx = load16(b + x), br = load16(b + x + 1);
		const __m256i horizontal = _mm256_add_epi16(cl, cr), vSum = _mm256_add_epi16(ux, bx);
		const __m256i cross = _mm256_srli_epi16(
			_mm256_add_epi16(_mm256_add_epi16(horizontal, vSum), two), 2);
		const __m256i diagonal = _mm256_srli_epi16(
			_mm256_add_epi16(_mm256_add_epi16(_mm256_add_epi16(ul, ur), _mm256_add_epi16(bl, br)), two), 2);
		const __m256i across = _mm256_srli_epi16(_mm256_add_epi16(horizontal, one), 1);
		const __m256i vertical = _mm256_srli_epi16(_mm256_add_epi16(vSum, one), 1);
		__m256i ch[3];
		for (int k = 0; k < 3; k++)
			ch[k] = _mm256_blendv_epi8(siteChannel<odd>(k, here, cross, diagonal, across, vertical),
						   siteChannel<even>(k, here, cross, diagonal, across, vertical),
						   evenLanes);
		// Bytes r0-7 g0-7 | r8-15 g8-15 and b0-7 twice | b8-15 twice; 24 bytes per half.
		const __m256i rg = _mm256_packus_epi16(ch[0], ch[1]);
		const __m256i bb = _mm256_packus_epi16(ch[2], ch[2]);
		uint8_t *out = d + 3 * x;
		for (int half = 0; half < 2; half++) {
			const __m128i rgh = half ? _mm256_extracti128_si256(rg, 1) : _mm256_castsi256_si128(rg);
			const __m128i bbh = half ? _mm256_extracti128_si256(bb, 1) : _mm256_castsi256_si128(bb);
			_mm_storeu_si128(reinterpret_cast<__m128i *>(out + 24 * half),
					 _mm_or_si128(_mm_shuffle_epi8(rgh, rg0), _mm_shuffle_epi8(bbh, b0)));
			_mm_storel_epi64(reinterpret_cast<__m128i *>(out + 24 * half + 16),
					 _mm_or_si128(_mm_shuffle_epi8(rgh, rg1), _mm_shuffle_epi8(bbh, b1)));
		}
	}
	demosaicTail<even, odd>(u, c, b, x, w, d);
}

} // namespace

void bayerToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
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
			demosaicRowAvx2<RedSite, GreenInRedRow>(u, c, b, w, d);
		else if (redRow)
			demosaicRowAvx2<GreenInRedRow, RedSite>(u, c, b, w, d);
		else if (f.redX == 0)
			demosaicRowAvx2<GreenInBlueRow, BlueSite>(u, c, b, w, d);
		else
			demosaicRowAvx2<BlueSite, GreenInBlueRow>(u, c, b, w, d);
	}
}

} // namespace kernels
} // namespace calped
