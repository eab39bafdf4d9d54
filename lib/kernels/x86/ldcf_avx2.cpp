// SPDX-License-Identifier: BSD-2-Clause
// LDCF's 5x5 filter with AVX2: sixteen outputs of a row at a time, each sample split into
// its two bytes so that _mm256_madd_epi16 multiplies adjacent taps' int16 pairs into exact
// 32-bit sums (opt/ldcf_body.h shows why they give the reference's rounding bit for bit).
// The plane's two-cell border, where the filter meets the zeros beyond it, is scalar.
// ldcfCell_avx2: one output of the filtered, half-size plane, each full-size value it
// needs as one row of eight samples per filter row (int32 lanes, byte split as above).
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

// The filter at (y, x) of the plane, every sample inside it and samples x - 2 .. x + 5 of
// each row read (x + 5 < width): L and H, the byte sums of opt/ldcf_body.h, over int32
// lanes (below 2^28: 25 x 255 x 2^15), then the reference's rounding and bias.
inline uint16_t filteredAt(const uint16_t *plane, ptrdiff_t stride, int y, int x,
			   const __m256i (&reversed)[kSize])
{
	const __m256i lowByte = _mm256_set1_epi32(0xFF);
	__m256i lo = _mm256_setzero_si256(), hi = _mm256_setzero_si256();
	for (int a = 0; a < kSize; a++) {
		// Filter row a meets samples (y + 2 - a, x - 2 .. x + 2), lanes 0-4.
		const __m128i row = _mm_loadu_si128(
			reinterpret_cast<const __m128i *>(plane + (y + kReach - a) * stride + x - kReach));
		const __m256i s = _mm256_cvtepu16_epi32(row);
		lo = _mm256_add_epi32(lo, _mm256_mullo_epi32(_mm256_and_si256(s, lowByte), reversed[a]));
		hi = _mm256_add_epi32(hi, _mm256_mullo_epi32(_mm256_srli_epi32(s, 8), reversed[a]));
	}
	// Lane sums: [L, H, L, H] after the two horizontal adds.
	const __m256i pairs = _mm256_hadd_epi32(lo, hi);
	__m128i t = _mm_add_epi32(_mm256_castsi256_si128(pairs), _mm256_extracti128_si256(pairs, 1));
	t = _mm_hadd_epi32(t, t);
	const int32_t l = _mm_cvtsi128_si32(t), h = _mm_extract_epi32(t, 1);
	return saturateU16(int64_t(ldcf::fromByteSums(h, l)) + kLdcfBias);
}

} // namespace

uint16_t ldcfCell_avx2(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const int32_t *filter, int size, const ResampleTap &xTap, const ResampleTap &yTap)
{
	if (!ldcf::cellVectorizable(width, height, size, xTap, yTap))
		return ldcfCell_ref(plane, stride, width, height, filter, size, xTap, yTap);
	// Each filter row reversed into lanes 0-4 (lane k meets sample x - 2 + k), zeros after.
	const __m256i firstFive = _mm256_setr_epi32(-1, -1, -1, -1, -1, 0, 0, 0);
	const __m256i reverse = _mm256_setr_epi32(4, 3, 2, 1, 0, 5, 6, 7);
	__m256i reversed[kSize];
	for (int a = 0; a < kSize; a++)
		reversed[a] = _mm256_permutevar8x32_epi32(_mm256_maskload_epi32(filter + a * kSize, firstFive), reverse);
	return ldcf::resampledCell(xTap, yTap,
				   [&](int y, int x) { return filteredAt(plane, stride, y, x, reversed); });
}

} // namespace kernels
} // namespace calped
