// SPDX-License-Identifier: BSD-2-Clause
// Orientation histograms over 4x4 cells with AVX2, for six orientations (every shrink-4
// model the toolbox ships): sixteen pixels of a cell row at a time, eight per 32-bit
// vector. Each pixel's two weighted magnitudes m * (1 - f) and m * f (Q10) are formed
// once and masked into the six bins' sums by comparing its bin with each, so the sums
// stay in registers over the cell's four rows; four cells' sums are then added across
// lanes together. Other orientation counts, and the cells right of the last block of
// four, use the portable body. Integer sums, so bit-identical to ref/aggregate_ref.cpp.
#include <immintrin.h>

#include "opt/hist_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kBins = 6;

// The six bins' sums of eight pixels (two cells) over the four rows of a cell row.
template <bool Interpolate>
void sumEightPixels(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, __m256i acc[kBins])
{
	const __m256i fracMask = _mm256_set1_epi32((1 << kOrientQ) - 1);
	for (int b = 0; b < kBins; b++)
		acc[b] = _mm256_setzero_si256();
	for (int dy = 0; dy < 4; dy++) {
		const __m256i m = _mm256_cvtepu16_epi32(
			_mm_loadu_si128(reinterpret_cast<const __m128i *>(mag + dy * stride)));
		const __m256i o = _mm256_cvtepu16_epi32(
			_mm_loadu_si128(reinterpret_cast<const __m128i *>(orient + dy * stride)));
		if (Interpolate) {
			// Bin o0 takes m * (1 - f), bin o0 + 1 (wrapping) m * f.
			const __m256i o0 = _mm256_srli_epi32(o, kOrientQ);
			const __m256i mf = _mm256_mullo_epi32(m, _mm256_and_si256(o, fracMask));
			const __m256i mg = _mm256_sub_epi32(_mm256_slli_epi32(m, kOrientQ), mf);
			__m256i inPrev = _mm256_cmpeq_epi32(o0, _mm256_set1_epi32(kBins - 1));
			for (int b = 0; b < kBins; b++) {
				const __m256i in = _mm256_cmpeq_epi32(o0, _mm256_set1_epi32(b));
				acc[b] = _mm256_add_epi32(acc[b], _mm256_add_epi32(_mm256_and_si256(in, mg),
										   _mm256_and_si256(inPrev, mf)));
				inPrev = in;
			}
		} else {
			// The nearest bin, the last one's upper half wrapping to bin 0, takes m.
			__m256i nearest = _mm256_srli_epi32(
				_mm256_add_epi32(o, _mm256_set1_epi32(1 << (kOrientQ - 1))), kOrientQ);
			nearest = _mm256_andnot_si256(_mm256_cmpeq_epi32(nearest, _mm256_set1_epi32(kBins)),
						      nearest);
			const __m256i mg = _mm256_slli_epi32(m, kOrientQ);
			for (int b = 0; b < kBins; b++)
				acc[b] = _mm256_add_epi32(
					acc[b], _mm256_and_si256(_mm256_cmpeq_epi32(nearest, _mm256_set1_epi32(b)), mg));
		}
	}
}

template <bool Interpolate>
void hist6(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int w4, int h4,
	   uint16_t *const *hist, ptrdiff_t histStride)
{
	const __m256i round = _mm256_set1_epi32(8 << kOrientQ);
	// hadd(hadd(left, right)) leaves the cells in the order 0, 2 | 1, 3.
	const __m256i cellOrder = _mm256_setr_epi32(0, 4, 1, 5, 0, 4, 1, 5);
	for (int cy = 0; cy < h4; cy++) {
		const ptrdiff_t row = 4 * cy * stride;
		for (int cx = 0; cx + 4 <= w4; cx += 4) {
			__m256i left[kBins], right[kBins];
			sumEightPixels<Interpolate>(mag + row + 4 * cx, orient + row + 4 * cx, stride, left);
			sumEightPixels<Interpolate>(mag + row + 4 * cx + 8, orient + row + 4 * cx + 8, stride,
						    right);
			for (int b = 0; b < kBins; b++) {
				const __m256i pairs = _mm256_hadd_epi32(left[b], right[b]);
				const __m256i cells = _mm256_permutevar8x32_epi32(_mm256_hadd_epi32(pairs, pairs),
										  cellOrder);
				// (sum + 8 * 2^kOrientQ) >> (4 + kOrientQ): at most 2^16, saturated by
				// the pack.
				const __m256i v = _mm256_srli_epi32(_mm256_add_epi32(cells, round), 4 + kOrientQ);
				const __m128i packed = _mm_packus_epi32(_mm256_castsi256_si128(v), _mm256_castsi256_si128(v));
				_mm_storel_epi64(reinterpret_cast<__m128i *>(hist[b] + cy * histStride + cx), packed);
			}
		}
	}
}

} // namespace

void gradHist4_avx2(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch)
{
	const int w4 = width / 4, h4 = height / 4;
	int done = 0; // cells of each cell row handled here
	if (nOrients == kBins) {
		if (interpolate)
			hist6<true>(mag, orient, stride, w4, h4, hist, histStride);
		else
			hist6<false>(mag, orient, stride, w4, h4, hist, histStride);
		done = w4 / 4 * 4;
	}
	if (done == w4)
		return;
	uint16_t *rest[16];
	for (int b = 0; b < nOrients; b++)
		rest[b] = hist[b] + done;
	gradHist4Body(mag + 4 * done, orient + 4 * done, stride, width - 4 * done, height, nOrients,
		      interpolate, rest, histStride, scratch);
}

} // namespace kernels
} // namespace calped
