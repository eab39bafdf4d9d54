// SPDX-License-Identifier: BSD-2-Clause
// Gradient normalisation M / (S + c) with AVX2, eight pixels at a time: mantissa and
// exponent of the denominator by binary search, the reciprocal by gather, the product in
// 64 bits. Bit-identical to ref/gradient_ref.cpp's normalizeMag_ref.
#include "kernels.h"
#include "fixed_point.h"
#include "x86/avx2_util.h"

namespace calped {
namespace kernels {

void normalizeMag_avx2(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		       const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height)
{
	const __m256i zero = _mm256_setzero_si256();
	for (int y = 0; y < height; y++) {
		uint16_t *mrow = mag + y * magStride;
		const uint32_t *srow = smoothedSum + y * sumStride;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			const __m256i d = _mm256_add_epi32(
				_mm256_loadu_si256(reinterpret_cast<const __m256i *>(srow + x)),
				_mm256_set1_epi32(int(t.normConst)));
			// Denominators below 2^11 (negative exponents: the mantissa needs a left
			// shift, which srlv cannot do), zero ones included, are rare (normConst ~ 0):
			// leave those blocks to the scalar code.
			const __m256i k = _mm256_sub_epi32(bitLength8(d), _mm256_set1_epi32(12));
			if (!_mm256_testz_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), k),
						_mm256_set1_epi32(-1)))
				break;
			const __m256i m = _mm256_srlv_epi32(d, k);
			const __m256i rcp = _mm256_i32gather_epi32(
				reinterpret_cast<const int *>(t.normRcp),
				_mm256_sub_epi32(m, _mm256_set1_epi32(2048)), 4);
			const __m256i mv = _mm256_cvtepu16_epi32(
				_mm_loadu_si128(reinterpret_cast<const __m128i *>(mrow + x)));
			const __m256i v = mulShiftRoundU(mv, rcp, _mm256_add_epi32(k, _mm256_set1_epi32(2)));
			// Saturate to 16 bits (values may exceed 32767, so compare unsigned-safely).
			const __m256i sat = _mm256_min_epu32(v, _mm256_set1_epi32(65535));
			const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(sat, zero), 0xD8);
			_mm_storeu_si128(reinterpret_cast<__m128i *>(mrow + x), _mm256_castsi256_si128(packed));
		}
		if (x < width)
			normalizeMag_ref(t, mrow + x, magStride, srow + x, sumStride, width - x, 1);
	}
}

} // namespace kernels
} // namespace calped
