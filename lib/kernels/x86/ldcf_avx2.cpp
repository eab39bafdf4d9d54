// SPDX-License-Identifier: BSD-2-Clause
// LDCF's 5x5 filter with AVX2: sixteen outputs of a row at a time, each sample split into
// its two bytes so that _mm256_madd_epi16 multiplies adjacent taps' int16 pairs into exact
// 32-bit sums (opt/ldcf_body.h shows why they give the reference's rounding bit for bit).
// The plane's two-cell border, where the filter meets the zeros beyond it, is scalar.
// ldcfCell_avx2: one output of the filtered, half-size plane from a block of the full-size
// values it needs, computed together from one load of each plane row they read.
#include <immintrin.h>

#include <algorithm>

#include "opt/ldcf_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kSize = 5, kReach = 2;

// Sixteen outputs (y, x0 .. x0 + 15), all of whose samples lie inside the plane.
inline void block16(const uint16_t *src, ptrdiff_t srcStride, int y, int x0,
		    const __m256i (&pairs)[kSize][3], uint16_t *dst)
{
	const __m256i lowByte = _mm256_set1_epi16(0x00FF), zero = _mm256_setzero_si256();
	__m256i loA = zero, loB = zero, hiA = zero, hiB = zero;
	for (int a = 0; a < kSize; a++) {
		// Tap (a, b) meets sample (y + 2 - a, x + 2 - b).
		const uint16_t *p = src + (y + kReach - a) * srcStride + x0 + kReach;
		__m256i lo[kSize + 1], hi[kSize + 1];
		for (int b = 0; b < kSize; b++) {
			const __m256i s = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p - b));
			lo[b] = _mm256_and_si256(s, lowByte);
			hi[b] = _mm256_srli_epi16(s, 8);
		}
		lo[kSize] = hi[kSize] = zero; // the fifth tap's partner, weight 0
		for (int k = 0; k < 3; k++) {
			const __m256i w = pairs[a][k];
			// unpacklo / unpackhi: outputs 0-3 and 8-11, and 4-7 and 12-15 (per 128-bit lane).
			loA = _mm256_add_epi32(loA, _mm256_madd_epi16(_mm256_unpacklo_epi16(lo[2 * k], lo[2 * k + 1]), w));
			loB = _mm256_add_epi32(loB, _mm256_madd_epi16(_mm256_unpackhi_epi16(lo[2 * k], lo[2 * k + 1]), w));
			hiA = _mm256_add_epi32(hiA, _mm256_madd_epi16(_mm256_unpacklo_epi16(hi[2 * k], hi[2 * k + 1]), w));
			hiB = _mm256_add_epi32(hiB, _mm256_madd_epi16(_mm256_unpackhi_epi16(hi[2 * k], hi[2 * k + 1]), w));
		}
	}
	// ldcf::fromByteSums, then the bias; packus saturates to [0, 65535] like the reference
	// and puts the two halves back in order within each lane.
	const __m256i round = _mm256_set1_epi32(256), bias = _mm256_set1_epi32(kLdcfBias);
	const __m256i a = _mm256_add_epi32(
		_mm256_srai_epi32(_mm256_add_epi32(_mm256_add_epi32(hiA, _mm256_srai_epi32(loA, 8)), round), 9), bias);
	const __m256i b = _mm256_add_epi32(
		_mm256_srai_epi32(_mm256_add_epi32(_mm256_add_epi32(hiB, _mm256_srai_epi32(loB, 8)), round), 9), bias);
	_mm256_storeu_si256(reinterpret_cast<__m256i *>(dst), _mm256_packus_epi32(a, b));
}

} // namespace

void ldcfFilter_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		     const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride)
{
	if (!ldcf::vectorizable(filter, size)) {
		ldcfFilter_ref(src, srcStride, width, height, filter, size, dst, dstStride);
		return;
	}
	// Taps (b, b + 1) of each filter row as int16 pairs (the first in the low half).
	__m256i pairs[kSize][3];
	for (int a = 0; a < kSize; a++)
		for (int k = 0; k < 3; k++) {
			const int32_t w0 = filter[a * kSize + 2 * k];
			const int32_t w1 = 2 * k + 1 < kSize ? filter[a * kSize + 2 * k + 1] : 0;
			pairs[a][k] = _mm256_set1_epi32(int32_t(uint32_t(uint16_t(w0)) | uint32_t(w1) << 16));
		}
	ldcf::border(src, srcStride, width, height, filter, size, dst, dstStride);
	const int inner = width - 2 * kReach;
	for (int y = kReach; y < height - kReach; y++) {
		uint16_t *out = dst + y * dstStride;
		if (inner < 16) {
			for (int x = kReach; x < width - kReach; x++)
				out[x] = ldcf::pixel(src, srcStride, width, height, filter, size, y, x);
			continue;
		}
		// The last block ends at the inner columns' end, overlapping the one before.
		for (int x0 = kReach;; x0 += 16) {
			x0 = std::min(x0, width - kReach - 16);
			block16(src, srcStride, y, x0, pairs, out + x0);
			if (x0 == width - kReach - 16)
				break;
		}
	}
}

namespace {

// The cell whose taps read full-size cells (y0 + r, x0 + j), r < Rows, j < Columns, every
// sample they need inside the plane. Their filtered values come from one load of each
// plane row they reach, eight samples from x0 - 2 in both 128-bit halves, split into
// bytes and multiplied by madd with the packed taps (column 2p in the low half, 2p + 1
// in the high): L and H of opt/ldcf_body.h in int32 lanes (below 2^28), then its rounding
// and the bias; then the taps.
template <int Rows, int Columns>
uint16_t cell(const uint16_t *plane, ptrdiff_t stride, const int16_t *packed, const ResampleTap &xTap,
	      const ResampleTap &yTap)
{
	constexpr int kPairs = (Columns + 1) / 2;
	const int y0 = yTap.first, x0 = xTap.first;
	const __m256i lowByte = _mm256_set1_epi16(0x00FF);
	__m256i lo[Rows][kPairs], hi[Rows][kPairs];
#pragma GCC unroll 4
	for (int r = 0; r < Rows; r++)
#pragma GCC unroll 2
		for (int p = 0; p < kPairs; p++)
			lo[r][p] = hi[r][p] = _mm256_setzero_si256();
#pragma GCC unroll 8
	for (int i = 0; i < Rows + 4; i++) {
		const __m256i s = _mm256_broadcastsi128_si256(_mm_loadu_si128(
			reinterpret_cast<const __m128i *>(plane + (y0 - kReach + i) * stride + x0 - kReach)));
		const __m256i sLo = _mm256_and_si256(s, lowByte), sHi = _mm256_srli_epi16(s, 8);
		// Plane row y0 - 2 + i meets filter row a = r + 4 - i of output row r.
#pragma GCC unroll 4
		for (int r = 0; r < Rows; r++) {
			const int a = r + 4 - i;
			if (a < 0 || a > 4)
				continue;
#pragma GCC unroll 2
			for (int p = 0; p < kPairs; p++) {
				const __m256i w = _mm256_loadu_si256(
					reinterpret_cast<const __m256i *>(packed + (a * 4 + 2 * p) * 8));
				lo[r][p] = _mm256_add_epi32(lo[r][p], _mm256_madd_epi16(sLo, w));
				hi[r][p] = _mm256_add_epi32(hi[r][p], _mm256_madd_epi16(sHi, w));
			}
		}
	}
	// Two accumulators at a time: per half [L, H, L', H'] by two horizontal adds, then
	// ldcf::fromByteSums in lanes 0 and 2, the bias and the reference's saturation.
	const __m256i round = _mm256_set1_epi32(256), bias = _mm256_set1_epi32(kLdcfBias);
	const __m256i zero = _mm256_setzero_si256(), top = _mm256_set1_epi32(65535);
	constexpr int kCount = Rows * kPairs;
	uint16_t filtered[Rows][Columns];
#pragma GCC unroll 8
	for (int n = 0; n < kCount; n += 2) {
		const int m = std::min(n + 1, kCount - 1);
		const __m256i u = _mm256_hadd_epi32(_mm256_hadd_epi32(lo[n / kPairs][n % kPairs], hi[n / kPairs][n % kPairs]),
						    _mm256_hadd_epi32(lo[m / kPairs][m % kPairs], hi[m / kPairs][m % kPairs]));
		const __m256i h = _mm256_shuffle_epi32(u, _MM_SHUFFLE(3, 3, 1, 1));
		const __m256i v = _mm256_min_epi32(_mm256_max_epi32(_mm256_add_epi32(
			_mm256_srai_epi32(_mm256_add_epi32(_mm256_add_epi32(h, _mm256_srai_epi32(u, 8)), round), 9), bias), zero), top);
		alignas(32) int32_t lanes[8];
		_mm256_store_si256(reinterpret_cast<__m256i *>(lanes), v);
#pragma GCC unroll 2
		for (int k = 0; k < 2; k++) {
			const int at = k == 0 ? n : m, r = at / kPairs, j = 2 * (at % kPairs);
			filtered[r][j] = uint16_t(lanes[2 * k]);
			if (j + 1 < Columns)
				filtered[r][j + 1] = uint16_t(lanes[4 + 2 * k]);
		}
	}
	return ldcf::resampledBlock(filtered, xTap, yTap);
}

using CellFn = uint16_t (*)(const uint16_t *, ptrdiff_t, const int16_t *, const ResampleTap &,
			    const ResampleTap &);
constexpr CellFn kCells[4][4] = {
	{ cell<1, 1>, cell<1, 2>, cell<1, 3>, cell<1, 4> },
	{ cell<2, 1>, cell<2, 2>, cell<2, 3>, cell<2, 4> },
	{ cell<3, 1>, cell<3, 2>, cell<3, 3>, cell<3, 4> },
	{ cell<4, 1>, cell<4, 2>, cell<4, 3>, cell<4, 4> },
};

} // namespace

uint16_t ldcfCell_avx2(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap)
{
	if (!ldcf::cellVectorizable(width, height, filter, xTap, yTap))
		return ldcfCell_ref(plane, stride, width, height, filter, xTap, yTap);
	return kCells[yTap.count - 1][xTap.count - 1](plane, stride, filter.packed, xTap, yTap);
}

} // namespace kernels
} // namespace calped
