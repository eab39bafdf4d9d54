// SPDX-License-Identifier: BSD-2-Clause
// convTri with radius 1 with AVX2, one pass per row: the vertical [1 2 1] of eight pixels
// at a time stays in registers (32-bit lanes), and the horizontal neighbours come from the
// blocks before and after it by a lane-crossing permute and a byte alignment. The row ends
// replicate their pixel as the reference does; a row's last pixels are its last block of
// eight, overlapping the one before. Bit-identical to ref/smooth_ref.cpp.
#include <immintrin.h>

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {

namespace {

// above + 2 * row + below of the eight pixels at a, b, c.
inline __m256i vertical8(const uint16_t *a, const uint16_t *b, const uint16_t *c)
{
	const __m256i va = _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i *>(a)));
	const __m256i vb = _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i *>(b)));
	const __m256i vc = _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i *>(c)));
	return _mm256_add_epi32(_mm256_add_epi32(va, vc), _mm256_add_epi32(vb, vb));
}

// (left + 2 * cur + right + 8) >> 4 of a block of eight vertical sums, where lane 7 of
// `before` is the sum left of the block and lane 0 of `after` the sum right of it.
inline __m256i horizontal8(__m256i before, __m256i cur, __m256i after)
{
	// [before.hi, cur.lo] aligned with cur by 12 bytes: each lane's left neighbour.
	const __m256i left = _mm256_alignr_epi8(cur, _mm256_permute2x128_si256(before, cur, 0x21), 12);
	// [cur.hi, after.lo] with cur by 4 bytes: each lane's right neighbour.
	const __m256i right = _mm256_alignr_epi8(_mm256_permute2x128_si256(cur, after, 0x21), cur, 4);
	const __m256i sum = _mm256_add_epi32(_mm256_add_epi32(left, right), _mm256_add_epi32(cur, cur));
	return _mm256_srli_epi32(_mm256_add_epi32(sum, _mm256_set1_epi32(8)), 4);
}

// Sixteen (store16) or eight (store8) 32-bit results, each below 2^16, stored as uint16.
inline void store16(uint16_t *out, __m256i lo, __m256i hi)
{
	const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(lo, hi), 0xD8);
	_mm256_storeu_si256(reinterpret_cast<__m256i *>(out), packed);
}

inline void store8(uint16_t *out, __m256i v)
{
	const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(v, v), 0xD8);
	_mm_storeu_si128(reinterpret_cast<__m128i *>(out), _mm256_castsi256_si128(packed));
}

} // namespace

void smoothTri1_avx2(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		     ptrdiff_t dstStride, int width, int height, uint32_t *)
{
	for (int y = 0; y < height; y++) {
		const uint16_t *a = src + std::max(y - 1, 0) * srcStride;
		const uint16_t *b = src + y * srcStride;
		const uint16_t *c = src + std::min(y + 1, height - 1) * srcStride;
		uint16_t *out = dst + y * dstStride;
		// The vertical sum at x, replicated past the row ends.
		auto vertical = [&](int x) {
			x = std::clamp(x, 0, width - 1);
			return uint32_t(a[x]) + 2 * uint32_t(b[x]) + uint32_t(c[x]);
		};
		// One block's right neighbour: the next block's sums when they exist, else
		// the one sum past the block (lane 0 is all that is read).
		auto after = [&](int x) {
			return x + 8 <= width ? vertical8(a + x, b + x, c + x)
					      : _mm256_set1_epi32(int(vertical(x)));
		};
		int x = 0;
		if (width >= 8) {
			__m256i before = _mm256_set1_epi32(int(vertical(0)));
			__m256i cur = vertical8(a, b, c);
			for (; x + 16 <= width; x += 16) {
				const __m256i cur1 = vertical8(a + x + 8, b + x + 8, c + x + 8);
				const __m256i next = after(x + 16);
				store16(out + x, horizontal8(before, cur, cur1), horizontal8(cur, cur1, next));
				before = cur1;
				cur = next;
			}
			if (x + 8 <= width) {
				store8(out + x, horizontal8(before, cur, after(x + 8)));
				x += 8;
			}
			// The last pixels as the row's last block of eight, overlapping the one
			// before (the same values written again).
			if (x < width) {
				const int last = width - 8;
				store8(out + last, horizontal8(_mm256_set1_epi32(int(vertical(last - 1))),
							       vertical8(a + last, b + last, c + last),
							       _mm256_set1_epi32(int(vertical(width)))));
				x = width;
			}
		}
		for (; x < width; x++)
			out[x] = static_cast<uint16_t>(
				(vertical(x - 1) + 2 * vertical(x) + vertical(x + 1) + 8) >> 4);
	}
}

} // namespace kernels
} // namespace calped
