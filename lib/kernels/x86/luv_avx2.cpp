// SPDX-License-Identifier: BSD-2-Clause
// RGB8 -> LUV (Q16) with AVX2, eight pixels at a time. Bit-identical to
// ref/luv_ref.cpp: the reference's 64-bit products are done with 32x32->64-bit
// multiplies on even and odd lanes; table reads are gathers.
#include <immintrin.h>

#include "kernels.h"
#include "fixed_point.h"
#include "x86/avx2_util.h"

namespace calped {
namespace kernels {

namespace {

// (a * b + 2^(S-1)) >> S per lane for signed a, b whose result fits 32 bits: the low 32
// bits of a logical 64-bit shift are the right ones even for negative products.
template <int S>
inline __m256i mulShiftRoundS(__m256i a, __m256i b)
{
	const __m256i half = _mm256_set1_epi64x(int64_t(1) << (S - 1));
	const __m256i pe = _mm256_add_epi64(_mm256_mul_epi32(a, b), half);
	const __m256i po = _mm256_add_epi64(
		_mm256_mul_epi32(_mm256_srli_epi64(a, 32), _mm256_srli_epi64(b, 32)), half);
	return _mm256_blend_epi32(_mm256_srli_epi64(pe, S), _mm256_slli_epi64(_mm256_srli_epi64(po, S), 32), 0xAA);
}

inline __m256i dot3(const int32_t c[3], __m256i r, __m256i g, __m256i b)
{
	return _mm256_add_epi32(_mm256_add_epi32(_mm256_mullo_epi32(r, _mm256_set1_epi32(c[0])),
						 _mm256_mullo_epi32(g, _mm256_set1_epi32(c[1]))),
				_mm256_mullo_epi32(b, _mm256_set1_epi32(c[2])));
}

void luv8(const LuvTables &t, const uint8_t *p, uint16_t *lo, uint16_t *uo, uint16_t *vo)
{
	// De-interleave 24 bytes into R, G, B.
	const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i *>(p));
	const __m128i c = _mm_loadl_epi64(reinterpret_cast<const __m128i *>(p + 16));
	auto pick = [&](int o) {
		const __m128i fromA = _mm_shuffle_epi8(
			a, _mm_setr_epi8(o, o + 3, o + 6, o + 9, o + 12, o + 15 < 16 ? o + 15 : -1,
					 -1, -1, -1, -1, -1, -1, -1, -1, -1, -1));
		const __m128i fromC = _mm_shuffle_epi8(
			c, _mm_setr_epi8(-1, -1, -1, -1, -1, o + 15 >= 16 ? o + 15 - 16 : -1, o + 2,
					 o + 5, -1, -1, -1, -1, -1, -1, -1, -1));
		return _mm256_cvtepu8_epi32(_mm_or_si128(fromA, fromC));
	};
	const __m256i r = pick(0), g = pick(1), b = pick(2);
	const __m256i zero = _mm256_setzero_si256();

	const __m256i X = dot3(t.cx, r, g, b), Y = dot3(t.cy, r, g, b), Z = dot3(t.cz, r, g, b);
	const __m256i L = gatherU16(t.l, _mm256_srli_epi32(Y, 18));
	const __m256i d = _mm256_add_epi32(
		_mm256_add_epi32(_mm256_srai_epi32(X, 2),
				 _mm256_mullo_epi32(_mm256_srai_epi32(Y, 2), _mm256_set1_epi32(15))),
		_mm256_mullo_epi32(_mm256_srai_epi32(Z, 2), _mm256_set1_epi32(3)));
	const __m256i dZero = _mm256_cmpeq_epi32(d, zero);

	// Mantissa m in [4096, 8192) and exponent k (may be negative) of d.
	const __m256i k = _mm256_sub_epi32(bitLength8(d), _mm256_set1_epi32(13));
	const __m256i kPos = _mm256_max_epi32(k, zero), kNeg = _mm256_max_epi32(_mm256_sub_epi32(zero, k), zero);
	__m256i m = _mm256_sllv_epi32(_mm256_srlv_epi32(d, kPos), kNeg);
	m = _mm256_blendv_epi8(m, _mm256_set1_epi32(4096), dZero); // keep the gather in range
	const __m256i rcp = _mm256_i32gather_epi32(reinterpret_cast<const int *>(t.rcp),
						   _mm256_sub_epi32(m, _mm256_set1_epi32(4096)), 4);
	const __m256i shift = _mm256_add_epi32(k, _mm256_set1_epi32(30 - kLuvRatioQ));
	__m256i xd = mulShiftRoundU(X, rcp, shift);
	__m256i yd = mulShiftRoundU(Y, rcp, shift);
	xd = _mm256_andnot_si256(dZero, xd);
	yd = _mm256_andnot_si256(dZero, yd);

	const __m256i tu = _mm256_sub_epi32(_mm256_mullo_epi32(xd, _mm256_set1_epi32(52)), _mm256_set1_epi32(t.un13));
	const __m256i tv = _mm256_sub_epi32(_mm256_mullo_epi32(yd, _mm256_set1_epi32(117)), _mm256_set1_epi32(t.vn13));
	const __m256i U = _mm256_sub_epi32(mulShiftRoundS<kLuvRatioQ>(L, tu), _mm256_set1_epi32(t.minu));
	const __m256i V = _mm256_sub_epi32(mulShiftRoundS<kLuvRatioQ>(L, tv), _mm256_set1_epi32(t.minv));

	// Saturate to uint16 and store (packus works per 128-bit lane, hence the permutes).
	const __m256i lu = _mm256_permute4x64_epi64(_mm256_packus_epi32(L, U), 0xD8);
	const __m256i vv = _mm256_permute4x64_epi64(_mm256_packus_epi32(V, V), 0xD8);
	_mm_storeu_si128(reinterpret_cast<__m128i *>(lo), _mm256_castsi256_si128(lu));
	_mm_storeu_si128(reinterpret_cast<__m128i *>(uo), _mm256_extracti128_si256(lu, 1));
	_mm_storeu_si128(reinterpret_cast<__m128i *>(vo), _mm256_castsi256_si128(vv));
}

} // namespace

void rgbToLuv_avx2(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		   int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride)
{
	for (int y = 0; y < height; y++) {
		const uint8_t *p = rgb + y * rgbStride;
		uint16_t *lo = l + y * stride, *uo = u + y * stride, *vo = v + y * stride;
		int x = 0;
		for (; x + 8 <= width; x += 8)
			luv8(t, p + 3 * x, lo + x, uo + x, vo + x);
		if (x < width)
			rgbToLuv_ref(t, p + 3 * x, rgbStride, width - x, 1, lo + x, uo + x, vo + x, stride);
	}
}

} // namespace kernels
} // namespace calped
