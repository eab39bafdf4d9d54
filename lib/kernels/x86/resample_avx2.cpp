// SPDX-License-Identifier: BSD-2-Clause
// Plane resampling with AVX2. The row pass, which the portable code does one sample at
// a time, works here on blocks of eight outputs whose taps all fall within 16
// consecutive source samples (any ratio below about 1.7): the 16 samples are loaded once
// and each tap's samples are picked by lane permutes. Blocks that shrink more (up to 8
// taps an output) multiply each output's 8 samples by its weights and add across lanes.
// Others, and the column pass, use the shared portable body. Bit-identical to
// ref/resample_ref.cpp.
#include <immintrin.h>

#include "opt/resample_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kChunk = 64; // blocks planned at a time (bounded stack use)

enum class BlockKind : int32_t { Scalar, Window, Wide };

// Up to 3 taps per output, all within 16 consecutive samples (ratios below about 1.7).
struct WindowPlan {
	int32_t base;        // first source sample of the block
	int32_t index[3][8]; // per tap: source sample - base, in [0, 16)
	int32_t weight[3][8];
};

// Shrinking by about 2 to 8: each output's up to 8 taps, weights 0 past its count.
struct WidePlan {
	int32_t first[8];
	int32_t weight[8][8];
};

struct BlockPlan {
	BlockKind kind;
	int32_t x0; // first output of the block
	union {
		WindowPlan window;
		WidePlan wide;
	};
};

bool planWindow(const ResampleTap *taps, int x0, int srcWidth, WindowPlan &p)
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
	p.base = base;
	return true;
}

bool planWide(const ResampleTap *taps, int x0, int srcWidth, WidePlan &p)
{
	for (int i = 0; i < 8; i++) {
		const ResampleTap &t = taps[x0 + i];
		if (t.count > 8 || t.first + 8 > srcWidth)
			return false;
		p.first[i] = t.first;
		for (int j = 0; j < 8; j++)
			p.weight[i][j] = j < t.count ? t.weight[j] : 0;
	}
	return true;
}

void planBlock(const ResampleTap *taps, int x0, int srcWidth, BlockPlan &p)
{
	p.x0 = x0;
	if (planWindow(taps, x0, srcWidth, p.window))
		p.kind = BlockKind::Window;
	else if (planWide(taps, x0, srcWidth, p.wide))
		p.kind = BlockKind::Wide;
	else
		p.kind = BlockKind::Scalar;
}

// The 32-bit lanes of lo (samples 0-7) or hi (8-15) that `index` names.
inline __m256i pick(__m256i lo, __m256i hi, __m256i index)
{
	const __m256i fromLo = _mm256_permutevar8x32_epi32(lo, index);
	const __m256i fromHi = _mm256_permutevar8x32_epi32(hi, index);
	return _mm256_blendv_epi8(fromLo, fromHi, _mm256_cmpgt_epi32(index, _mm256_set1_epi32(7)));
}

// The weighted sums of a window block's eight outputs, added to acc.
inline __m256i windowSums(const WindowPlan &p, const uint16_t *in, __m256i acc)
{
	const __m256i s16 = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + p.base));
	const __m256i lo = _mm256_cvtepu16_epi32(_mm256_castsi256_si128(s16));
	const __m256i hi = _mm256_cvtepu16_epi32(_mm256_extracti128_si256(s16, 1));
	for (int j = 0; j < 3; j++) {
		const __m256i idx = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.index[j]));
		const __m256i w = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.weight[j]));
		acc = _mm256_add_epi32(acc, _mm256_mullo_epi32(pick(lo, hi, idx), w));
	}
	return acc;
}

// The same for a wide block: each output's 8 samples times its 8 weights, summed across
// lanes (products below 2^31, sums below 2^32, so the wrapping adds are exact).
inline __m256i wideSums(const WidePlan &p, const uint16_t *in, __m256i acc)
{
	__m256i prod[8];
	for (int i = 0; i < 8; i++) {
		const __m256i s = _mm256_cvtepu16_epi32(
			_mm_loadu_si128(reinterpret_cast<const __m128i *>(in + p.first[i])));
		const __m256i w = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.weight[i]));
		prod[i] = _mm256_mullo_epi32(s, w);
	}
	// Pairwise adds leave, in each 128-bit half, partial sums of outputs 0-3 (g0) and 4-7
	// (g1); the two halves then add up.
	const __m256i g0 = _mm256_hadd_epi32(_mm256_hadd_epi32(prod[0], prod[1]),
					     _mm256_hadd_epi32(prod[2], prod[3]));
	const __m256i g1 = _mm256_hadd_epi32(_mm256_hadd_epi32(prod[4], prod[5]),
					     _mm256_hadd_epi32(prod[6], prod[7]));
	return _mm256_add_epi32(acc, _mm256_add_epi32(_mm256_permute2x128_si256(g0, g1, 0x20),
						      _mm256_permute2x128_si256(g0, g1, 0x31)));
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
			planBlock(xTaps, chunk + 8 * b, srcWidth, plans[b]);
		// The last few outputs: one more block ending at the row's end, overlapping
		// the one before (it writes the same values there), or one sample at a time.
		int tail = chunk + 8 * blocks;
		if (tail < end && dstWidth >= 8) {
			planBlock(xTaps, dstWidth - 8, srcWidth, plans[blocks++]);
			tail = end;
		}
		for (int y = 0; y < srcHeight; y++) {
			const uint16_t *in = src + y * srcStride;
			uint16_t *out = tmp + y * tmpStride;
			for (int b = 0; b < blocks; b++) {
				const BlockPlan &p = plans[b];
				const int x0 = p.x0;
				__m256i acc;
				if (p.kind == BlockKind::Window) {
					acc = windowSums(p.window, in, half);
				} else if (p.kind == BlockKind::Wide) {
					acc = wideSums(p.wide, in, half);
				} else {
					for (int x = x0; x < x0 + 8; x++)
						out[x] = roundQ14(tapSum(xTaps[x], in));
					continue;
				}
				// Rounded unsigned sums below 2^32: shift logically, saturate to 16 bits.
				const __m256i v = _mm256_min_epu32(_mm256_srli_epi32(acc, kQ), max);
				const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(v, v), 0xD8);
				_mm_storeu_si128(reinterpret_cast<__m128i *>(out + x0), _mm256_castsi256_si128(packed));
			}
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
