// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation with AVX2: the per-pixel part (normalisation,
// square-root and orientation tables) eight pixels at a time, with gathers. Compiled with
// -mavx2 and used only when the CPU has AVX2. Bit-identical to ref/gradient_ref.cpp:
// the reference's 64-bit products gx * rsqrt / 2^(8 + k/2) are computed here as
// (gx << (10 - k/2)) * rsqrt / 2^18, which is the same integer and fits 32 bits
// because |gx| <= sqrt(m2).
#include <immintrin.h>

#include <cstddef>

#include "opt/gradient_rows.h"
#include "x86/avx2_util.h"

namespace calped {
namespace kernels {

namespace {

// The three orientation tables are read through one base pointer (see the static_asserts).
static_assert(offsetof(GradientTables, fromSinAcute) ==
		      offsetof(GradientTables, fromCos) + sizeof(uint16_t) * (2 * 4096 + 1),
	      "orientation tables are contiguous");
static_assert(offsetof(GradientTables, fromSinObtuse) ==
		      offsetof(GradientTables, fromSinAcute) + sizeof(uint16_t) * (4096 + 1),
	      "orientation tables are contiguous");

void gradientPixels8(const GradientTables &t, const int32_t *gxp, const int32_t *gyp,
		     uint16_t *mag, uint16_t *orient)
{
	const __m256i gx = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(gxp));
	const __m256i gy = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(gyp));
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

	const __m256i rs = _mm256_i32gather_epi32(reinterpret_cast<const int *>(t.rsqrtQ20), m, 4);
	const __m256i gyNeg = _mm256_cmpgt_epi32(zero, gy);
	const __m256i gxf = _mm256_blendv_epi8(gx, _mm256_sub_epi32(zero, gx), gyNeg);
	const __m256i gyAbs = _mm256_abs_epi32(gy);
	const __m256i up = _mm256_sub_epi32(_mm256_set1_epi32(10), halfK);
	const __m256i half = _mm256_set1_epi32(1 << 17);
	__m256i c12 = _mm256_srai_epi32(
		_mm256_add_epi32(_mm256_mullo_epi32(_mm256_sllv_epi32(gxf, up), rs), half), 18);
	c12 = _mm256_max_epi32(_mm256_min_epi32(c12, _mm256_set1_epi32(4096)), _mm256_set1_epi32(-4096));
	__m256i s12 = _mm256_srai_epi32(
		_mm256_add_epi32(_mm256_mullo_epi32(_mm256_sllv_epi32(gyAbs, up), rs), half), 18);
	s12 = _mm256_min_epi32(s12, _mm256_set1_epi32(4096));

	// Index into fromCos / fromSinAcute / fromSinObtuse laid end to end.
	const __m256i useCos = _mm256_and_si256(_mm256_cmpgt_epi32(c12, _mm256_set1_epi32(-2897)),
						_mm256_cmpgt_epi32(_mm256_set1_epi32(2897), c12));
	const __m256i cosIndex = _mm256_add_epi32(c12, _mm256_set1_epi32(4096));
	const __m256i sinBase = _mm256_blendv_epi8(_mm256_set1_epi32(8193 + 4097),
						   _mm256_set1_epi32(8193),
						   _mm256_cmpgt_epi32(c12, zero));
	__m256i index = _mm256_blendv_epi8(_mm256_add_epi32(sinBase, s12), cosIndex, useCos);
	index = _mm256_blendv_epi8(index, _mm256_set1_epi32(4096), isZero);
	const __m256i o = gatherU16(t.fromCos, index);

	// Pack to uint16 (packus works per 128-bit lane, hence the permute).
	const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(magv, o), 0xD8);
	_mm_storeu_si128(reinterpret_cast<__m128i *>(mag), _mm256_castsi256_si128(packed));
	_mm_storeu_si128(reinterpret_cast<__m128i *>(orient), _mm256_extracti128_si256(packed, 1));
}

} // namespace

void gradMagOrient_avx2(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *scratch)
{
	int32_t *bx = scratch, *by = bx + width, *cx = by + width, *cy = cx + width;
	for (int y = 0; y < height; y++) {
		strongestGradientRow(planes, stride, width, height, y, bx, by, cx, cy);
		uint16_t *mo = mag + y * outStride;
		uint16_t *oo = orient + y * outStride;
		int x = 0;
		for (; x + 8 <= width; x += 8)
			gradientPixels8(t, bx + x, by + x, mo + x, oo + x);
		for (; x < width; x++)
			gradientPixel(t, bx[x], by[x], mo + x, oo + x);
	}
}

} // namespace kernels
} // namespace calped
