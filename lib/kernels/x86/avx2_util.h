// SPDX-License-Identifier: BSD-2-Clause
// Small AVX2 helpers shared by the x86 kernels (compiled with -mavx2 only).
#pragma once

#include <immintrin.h>

namespace calped {
namespace kernels {
namespace {

// Number of significant bits of each 32-bit lane (0 for 0), from the exponent of its
// half converted to float. The conversion rounds to nearest, so the exponent may be one
// too large (when rounding carries into the next power of two); shifting the half down
// by it then leaves 0, which corrects it.
inline __m256i bitLength8(__m256i v)
{
	const __m256i half = _mm256_srli_epi32(v, 1); // below 2^31: a non-negative int
	__m256i e = _mm256_srli_epi32(_mm256_castps_si256(_mm256_cvtepi32_ps(half)), 23);
	e = _mm256_sub_epi32(e, _mm256_set1_epi32(127)); // floor(log2(half)), or one more
	const __m256i over = _mm256_cmpeq_epi32(_mm256_srlv_epi32(half, e), _mm256_setzero_si256());
	e = _mm256_add_epi32(e, over);
	// bitLength(v) = floor(log2(half)) + 2 for v >= 2; v itself for 0 and 1 (whose e is
	// far below).
	return _mm256_max_epi32(_mm256_add_epi32(e, _mm256_set1_epi32(2)),
				_mm256_min_epu32(v, _mm256_set1_epi32(1)));
}

// (a * b + 2^(s-1)) >> s per 32-bit lane, for non-negative a and b whose 64-bit product
// shifted fits 32 bits; s per lane in [1, 63].
inline __m256i mulShiftRoundU(__m256i a, __m256i b, __m256i s)
{
	const __m256i one = _mm256_set1_epi64x(1);
	const __m256i sEven = _mm256_and_si256(s, _mm256_set1_epi64x(0xFFFFFFFF));
	const __m256i sOdd = _mm256_srli_epi64(s, 32);
	const __m256i pe = _mm256_mul_epu32(a, b);
	const __m256i po = _mm256_mul_epu32(_mm256_srli_epi64(a, 32), _mm256_srli_epi64(b, 32));
	const __m256i re = _mm256_srlv_epi64(
		_mm256_add_epi64(pe, _mm256_sllv_epi64(one, _mm256_sub_epi64(sEven, one))), sEven);
	const __m256i ro = _mm256_srlv_epi64(
		_mm256_add_epi64(po, _mm256_sllv_epi64(one, _mm256_sub_epi64(sOdd, one))), sOdd);
	return _mm256_blend_epi32(re, _mm256_slli_epi64(ro, 32), 0xAA);
}

// uint16 values of a table at 32-bit indices (reads two bytes past the last entry,
// which callers keep inside their table structs).
inline __m256i gatherU16(const uint16_t *table, __m256i index)
{
	return _mm256_and_si256(
		_mm256_i32gather_epi32(reinterpret_cast<const int *>(table), index, 2),
		_mm256_set1_epi32(0xFFFF));
}

} // namespace
} // namespace kernels
} // namespace calped
