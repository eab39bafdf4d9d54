// SPDX-License-Identifier: BSD-2-Clause
// 2x2 block averages (shrink 2) with AVX2: eight cells from sixteen pixels of each of the
// cell's two rows. Sums of four uint16 (< 2^18) in 32-bit lanes, rounded as the reference
// (ref/aggregate2_ref.cpp); cells left over at the right use the same scalar arithmetic.
#include <immintrin.h>

#include "kernels.h"

namespace calped {
namespace kernels {

void shrink2_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	const int w2 = width / 2, h2 = height / 2;
	const int shift = 2 + extraShift;
	const uint32_t half = 1u << (shift - 1);
	const __m256i low = _mm256_set1_epi32(0xFFFF), rounding = _mm256_set1_epi32(int(half));
	const __m128i count = _mm_cvtsi32_si128(shift);
	for (int cy = 0; cy < h2; cy++) {
		const uint16_t *r0 = src + 2 * cy * srcStride, *r1 = r0 + srcStride;
		uint16_t *out = dst + cy * dstStride;
		int cx = 0;
		for (; cx + 8 <= w2; cx += 8) {
			// Each 32-bit lane holds a cell's two pixels of a row: low half + high half.
			const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(r0 + 2 * cx));
			const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(r1 + 2 * cx));
			const __m256i sum = _mm256_add_epi32(
				_mm256_add_epi32(_mm256_and_si256(a, low), _mm256_srli_epi32(a, 16)),
				_mm256_add_epi32(_mm256_and_si256(b, low), _mm256_srli_epi32(b, 16)));
			const __m256i q = _mm256_srl_epi32(_mm256_add_epi32(sum, rounding), count);
			// packus works per 128-bit lane: cells 0-3 and 4-7 end up in 64-bit words 0 and 2.
			const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(q, q), 0xD8);
			_mm_storeu_si128(reinterpret_cast<__m128i *>(out + cx), _mm256_castsi256_si128(packed));
		}
		for (; cx < w2; cx++)
			out[cx] = static_cast<uint16_t>((uint32_t(r0[2 * cx]) + r0[2 * cx + 1] + r1[2 * cx] +
							 r1[2 * cx + 1] + half) >> shift);
	}
}

} // namespace kernels
} // namespace calped
