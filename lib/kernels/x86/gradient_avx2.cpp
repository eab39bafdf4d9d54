// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation with AVX2, eight pixels at a time in one pass per
// row: each colour channel's doubled derivatives (from the row's neighbours and the rows
// above and below), the strongest channel kept, then the per-pixel part (normalisation,
// square-root and orientation tables) with gathers. The first and last pixel of a row
// (one-sided differences) and rows of a one-row image go through the scalar path.
// Compiled with -mavx2 and used only when the CPU has AVX2. Bit-identical to
// ref/gradient_ref.cpp: the reference's cosine gx * rsqrt * 2^-(20 + k/2) is formed here as
// (gx << (10 - k/2)) * rsqrt = cos * 2^30, which fits 32 bits because |gx| <= sqrt(m2)
// < sqrt((m + 1) * 2^k) and rsqrtQ20[m] is at most 2^-13 above 2^20 / sqrt(m) (so
// |cos * 2^30| < 2^30 * (1 + 2^-10)); its product with 10000 is taken in 64-bit lanes.
#include <immintrin.h>

#include <cstddef>
#include <initializer_list>

#include "opt/gradient_rows.h"
#include "x86/avx2_util.h"

namespace calped {
namespace kernels {

namespace {

// gatherU16 reads two bytes past the entry it wants: the last fromCos entry has nOrients after it.
static_assert(offsetof(GradientTables, nOrients) >=
		      offsetof(GradientTables, fromCos) + sizeof(uint16_t) * (2 * kCosSteps + 2),
	      "fromCos is followed by readable bytes");

// (|p| * 10000) >> 30 per lane, for |p| < 2^31 (even and odd lanes multiplied apart).
inline __m256i cosSteps8(__m256i absP)
{
	const __m256i steps = _mm256_set1_epi32(kCosSteps);
	const __m256i even = _mm256_srli_epi64(_mm256_mul_epu32(absP, steps), 30);
	const __m256i odd = _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(absP, 32), steps), 30);
	return _mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xAA);
}

// Magnitude and orientation of eight pixels from their doubled derivatives.
void gradientPixels8(const GradientTables &t, __m256i gx, __m256i gy, uint16_t *mag, uint16_t *orient)
{
	const __m256i zero = _mm256_setzero_si256();
	const __m256i m2 = _mm256_add_epi32(_mm256_mullo_epi32(gx, gx), _mm256_mullo_epi32(gy, gy));
	const __m256i isZero = _mm256_cmpeq_epi32(m2, zero);

	// k = bitLength - 12, at least 0, rounded up to even; m = m2 >> k.
	__m256i k = _mm256_max_epi32(_mm256_sub_epi32(bitLength8(m2), _mm256_set1_epi32(12)), zero);
	k = _mm256_add_epi32(k, _mm256_and_si256(k, _mm256_set1_epi32(1)));
	const __m256i m = _mm256_srlv_epi32(m2, k);
	const __m256i halfK = _mm256_srli_epi32(k, 1);

	const __m256i sq = gatherU16(t.sqrtQ8, m);
	__m256i magv = _mm256_srli_epi32(
		_mm256_add_epi32(_mm256_sllv_epi32(sq, halfK), _mm256_set1_epi32(256)), 9);
	magv = _mm256_andnot_si256(isZero, magv);

	// cos * 2^30 of the orientation folded into [0, pi), then the toolbox's acos index
	// trunc(cos * 10000). m2 = 0 reads rsqrtQ20[0] = 0: cosine 0, orientation acos(0).
	const __m256i rs = _mm256_i32gather_epi32(reinterpret_cast<const int *>(t.rsqrtQ20), m, 4);
	const __m256i gyNeg = _mm256_cmpgt_epi32(zero, gy);
	const __m256i gxf = _mm256_blendv_epi8(gx, _mm256_sub_epi32(zero, gx), gyNeg);
	const __m256i up = _mm256_sub_epi32(_mm256_set1_epi32(10), halfK);
	const __m256i p = _mm256_mullo_epi32(_mm256_sllv_epi32(gxf, up), rs);
	const __m256i c = _mm256_min_epi32(cosSteps8(_mm256_abs_epi32(p)), _mm256_set1_epi32(kCosSteps));
	const __m256i index = _mm256_add_epi32(_mm256_sign_epi32(c, p), _mm256_set1_epi32(kCosSteps));
	const __m256i o = gatherU16(t.fromCos, index);

	// Pack to uint16 (packus works per 128-bit lane, hence the permute).
	const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(magv, o), 0xD8);
	_mm_storeu_si128(reinterpret_cast<__m128i *>(mag), _mm256_castsi256_si128(packed));
	_mm_storeu_si128(reinterpret_cast<__m128i *>(orient), _mm256_extracti128_si256(packed, 1));
}

inline __m256i load8(const uint16_t *p)
{
	return _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i *>(p)));
}

inline __m256i clampDiff8(__m256i v)
{
	return _mm256_max_epi32(_mm256_min_epi32(v, _mm256_set1_epi32(46340)), _mm256_set1_epi32(-46340));
}

// The strongest channel's doubled derivatives of eight pixels x .. x + 7 of a row, for
// 1 <= x and x + 8 < width (central differences across); vShift doubles the vertical
// one on the first and last rows. The earlier channel wins ties, as in the reference.
inline void strongest8(const uint16_t *const planes[3], ptrdiff_t rowOffset, ptrdiff_t upOffset,
		       ptrdiff_t downOffset, __m128i vShift, __m256i &gx, __m256i &gy)
{
	__m256i best = _mm256_setzero_si256();
	for (int c = 0; c < 3; c++) {
		const uint16_t *row = planes[c] + rowOffset;
		const __m256i cx = clampDiff8(_mm256_sub_epi32(load8(row + 1), load8(row - 1)));
		const __m256i cy = clampDiff8(_mm256_sll_epi32(
			_mm256_sub_epi32(load8(planes[c] + downOffset), load8(planes[c] + upOffset)), vShift));
		const __m256i m2 = _mm256_add_epi32(_mm256_mullo_epi32(cx, cx), _mm256_mullo_epi32(cy, cy));
		if (c == 0) {
			gx = cx;
			gy = cy;
			best = m2;
			continue;
		}
		// Where best >= m2 (unsigned) the earlier channel stays.
		const __m256i larger = _mm256_max_epu32(m2, best);
		const __m256i keep = _mm256_cmpeq_epi32(larger, best);
		gx = _mm256_blendv_epi8(cx, gx, keep);
		gy = _mm256_blendv_epi8(cy, gy, keep);
		best = larger;
	}
}

} // namespace

void gradMagOrient_avx2(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *scratch)
{
	int32_t *bx = scratch, *by = bx + width, *cx = by + width, *cy = cx + width;
	for (int y = 0; y < height; y++) {
		uint16_t *mo = mag + y * outStride;
		uint16_t *oo = orient + y * outStride;
		// Rows too short for a block, and a one-row image: the whole row in scalar.
		if (width < 10 || height < 2) {
			strongestGradientRow(planes, stride, width, height, y, bx, by, cx, cy);
			for (int x = 0; x < width; x++)
				gradientPixel(t, bx[x], by[x], mo + x, oo + x);
			continue;
		}
		const int up = y > 0 ? y - 1 : y, down = y < height - 1 ? y + 1 : y;
		const __m128i vShift = _mm_cvtsi32_si128(y == 0 || y == height - 1 ? 1 : 0);
		// Blocks of eight from x = 1; the last block ends at width - 2 and may overlap
		// the one before (the same values written again).
		for (int x = 1;; x += 8) {
			x = x + 8 < width ? x : width - 9;
			__m256i gx, gy;
			strongest8(planes, y * stride + x, up * stride + x, down * stride + x, vShift, gx, gy);
			gradientPixels8(t, gx, gy, mo + x, oo + x);
			if (x == width - 9)
				break;
		}
		// The first and last pixel: one-sided horizontal differences.
		for (int x : { 0, width - 1 }) {
			int32_t gx = 0, gy = 0;
			strongestGradientAt(planes, stride, width, height, x, y, gx, gy);
			gradientPixel(t, gx, gy, mo + x, oo + x);
		}
	}
}

} // namespace kernels
} // namespace calped
