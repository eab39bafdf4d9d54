// SPDX-License-Identifier: BSD-2-Clause
// Plane resampling with AVX2. The row pass, which the portable code does one sample at
// a time, works here on blocks of eight outputs whose taps all fall within 16
// consecutive source samples (any ratio below about 1.7): the 16 samples are loaded once
// and each tap's samples are picked by lane permutes. Other blocks, and the column pass,
// use the shared portable body. Bit-identical to ref/resample_ref.cpp.
#include <immintrin.h>

#include "opt/resample_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kChunk = 64; // blocks planned at a time (bounded stack use)

struct BlockPlan {
	int32_t x0;          // first output of the block
	int32_t base;        // first source sample of the block, or -1: not planned
	int32_t index[3][8]; // per tap: source sample - base, in [0, 16)
	int32_t weight[3][8];
};

bool planBlock(const ResampleTap *taps, int x0, int srcWidth, BlockPlan &p)
{
	// The 16 samples start at the block's first tap, or earlier at the right edge so
	// that they stay inside the row.
	const int base = std::min(taps[x0].first, srcWidth - 16);
	if (base < 0)
		return false;
	for (int i = 0; i < 8; i++) {
		const ResampleTap &t = taps[x0 + i];
		if (t.count > 3 || t.first < base || t.first + t.count - base > 16)
			return false;
		for (int j = 0; j < 3; j++) {
			p.index[j][i] = j < t.count ? t.first + j - base : t.first - base;
			p.weight[j][i] = j < t.count ? t.weight[j] : 0;
		}
	}
	p.x0 = x0;
	p.base = base;
	return true;
}

// The 32-bit lanes of lo (samples 0-7) or hi (8-15) that `index` names.
inline __m256i pick(__m256i lo, __m256i hi, __m256i index)
{
	const __m256i fromLo = _mm256_permutevar8x32_epi32(lo, index);
	const __m256i fromHi = _mm256_permutevar8x32_epi32(hi, index);
	return _mm256_blendv_epi8(fromLo, fromHi, _mm256_cmpgt_epi32(index, _mm256_set1_epi32(7)));
}

inline uint32_t tapSum(const ResampleTap &t, const uint16_t *in)
{
	uint32_t acc = 0;
	for (int j = 0; j < t.count; j++)
		acc += uint32_t(t.weight[j]) * in[t.first + j];
	return acc;
}

bool isHalving(const ResampleTap *taps, int dstWidth)
{
	for (int x = 0; x < dstWidth; x++) {
		const ResampleTap &t = taps[x];
		if (t.count != 2 || t.first != 2 * x || t.weight[0] != kOne / 2 || t.weight[1] != kOne / 2)
			return false;
	}
	return true;
}

// Exactly half the width: (a + b + 1) >> 1 is the unsigned average instruction.
void halveRows(const uint16_t *src, ptrdiff_t srcStride, int srcHeight, int dstWidth,
	       uint16_t *tmp, ptrdiff_t tmpStride)
{
	const __m256i lowHalf = _mm256_set1_epi32(0xFFFF);
	for (int y = 0; y < srcHeight; y++) {
		const uint16_t *in = src + y * srcStride;
		uint16_t *out = tmp + y * tmpStride;
		int x = 0;
		for (; x + 16 <= dstWidth; x += 16) {
			const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + 2 * x));
			const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + 2 * x + 16));
			// Even samples in the low halves of 32-bit lanes, odd ones in the high halves.
			const __m256i even = _mm256_packus_epi32(_mm256_and_si256(a, lowHalf), _mm256_and_si256(b, lowHalf));
			const __m256i odd = _mm256_packus_epi32(_mm256_srli_epi32(a, 16), _mm256_srli_epi32(b, 16));
			const __m256i avg = _mm256_permute4x64_epi64(_mm256_avg_epu16(even, odd), 0xD8);
			_mm256_storeu_si256(reinterpret_cast<__m256i *>(out + x), avg);
		}
		for (; x < dstWidth; x++)
			out[x] = static_cast<uint16_t>((uint32_t(in[2 * x]) + in[2 * x + 1] + 1) >> 1);
	}
}

void rowPass(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
	     int dstWidth, const ResampleTap *xTaps, uint16_t *tmp, ptrdiff_t tmpStride)
{
	if (isHalving(xTaps, dstWidth)) {
		halveRows(src, srcStride, srcHeight, dstWidth, tmp, tmpStride);
		return;
	}
	BlockPlan plans[kChunk + 1];
	const __m256i half = _mm256_set1_epi32(1 << (kQ - 1)), max = _mm256_set1_epi32(65535);
	for (int chunk = 0; chunk < dstWidth; chunk += 8 * kChunk) {
		int blocks = std::min(kChunk, (dstWidth - chunk) / 8);
		const int end = std::min(dstWidth, chunk + 8 * kChunk);
		for (int b = 0; b < blocks; b++)
			if (!planBlock(xTaps, chunk + 8 * b, srcWidth, plans[b]))
				plans[b] = BlockPlan{ chunk + 8 * b, -1, {}, {} };
		// The last few outputs: one more block ending at the row's end, overlapping
		// the one before (it writes the same values there), or one sample at a time.
		const int tail = chunk + 8 * blocks;
		bool scalarTail = tail < end;
		if (scalarTail && dstWidth >= 8 && planBlock(xTaps, dstWidth - 8, srcWidth, plans[blocks])) {
			blocks++;
			scalarTail = false;
		}
		for (int y = 0; y < srcHeight; y++) {
			const uint16_t *in = src + y * srcStride;
			uint16_t *out = tmp + y * tmpStride;
			for (int b = 0; b < blocks; b++) {
				const BlockPlan &p = plans[b];
				const int x0 = p.x0;
				if (p.base < 0) {
					for (int x = x0; x < x0 + 8; x++)
						out[x] = roundQ14(tapSum(xTaps[x], in));
					continue;
				}
				const __m256i s16 = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + p.base));
				const __m256i lo = _mm256_cvtepu16_epi32(_mm256_castsi256_si128(s16));
				const __m256i hi = _mm256_cvtepu16_epi32(_mm256_extracti128_si256(s16, 1));
				__m256i acc = half;
				for (int j = 0; j < 3; j++) {
					const __m256i idx = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.index[j]));
					const __m256i w = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.weight[j]));
					acc = _mm256_add_epi32(acc, _mm256_mullo_epi32(pick(lo, hi, idx), w));
				}
				// Unsigned sums below 2^32: shift logically, then saturate to 16 bits.
				const __m256i v = _mm256_min_epu32(_mm256_srli_epi32(acc, kQ), max);
				const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(v, v), 0xD8);
				_mm_storeu_si128(reinterpret_cast<__m128i *>(out + x0), _mm256_castsi256_si128(packed));
			}
			if (scalarTail)
				for (int x = tail; x < end; x++)
					out[x] = roundQ14(tapSum(xTaps[x], in));
		}
	}
}

} // namespace

void resamplePlane_avx2(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
			ptrdiff_t tmpStride)
{
	rowPass(src, srcStride, srcWidth, srcHeight, dstWidth, xTaps, tmp, tmpStride);
	resampleColumnsBody(dst, dstStride, dstWidth, dstHeight, yTaps, tmp, tmpStride);
}

} // namespace kernels
} // namespace calped
