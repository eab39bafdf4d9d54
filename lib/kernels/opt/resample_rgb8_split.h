// SPDX-License-Identifier: BSD-2-Clause
// Planning for the SIMD RGB8 resamplers that work at any ratio in 32-bit lanes.
//
// The reference sums sum_y wy * sum_x wx * p in 64 bits (up to 255 * 2^28) and rounds
// with (acc + 2^27 - 1) >> 28. With weights in [0, 2^14] summing to at most 2^14 per tap,
// the SIMD kernels instead take the row sums first, H = sum_x wx * p < 2^22 (16-bit pairs
// of samples and weights, one multiply-add each), split H = hi * 2^14 + lo with hi < 2^8
// and lo < 2^14, and sum the columns separately:
//   A = sum_y wy * hi < 2^22,   B = sum_y wy * lo < 2^28,   acc = A * 2^14 + B,
//   out = (acc + 2^27 - 1) >> 28 = (A + ((B + 2^27 - 1) >> 14)) >> 14
// (floor(floor(x / a) / b) = floor(x / (a b))), all in 32 bits and exact.
//
// A "quad" is four consecutive output samples (interleaved RGB, so 4/3 of a pixel): all
// the source bytes its taps read lie within a window of 16 bytes of one row (32 when
// shrinking by more than about 2.5x), loaded once and picked by a byte shuffle or table
// lookup into (first, second) pairs of 16-bit samples beside pairs of weights.
#pragma once

#include <cstdint>

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

constexpr int kSplitMaxSteps = 3; // pair steps of the horizontal multiply-add
constexpr int kSplitNarrow = 16, kSplitWide = 32; // window bytes
constexpr uint8_t kZeroByte = 0x80; // a shuffle index that yields 0

// Taps per output sample a window can serve: two pair steps in 16 bytes, three in 32.
inline int splitMaxXTaps(int window)
{
	return window == kSplitNarrow ? 4 : 2 * kSplitMaxSteps;
}

// Whether every tap has 1..maxCount weights in [0, 2^14] summing to at most 2^14: then
// the split sums above cannot overflow.
inline bool splitSumsFit(const ResampleTap *taps, int n, int maxCount)
{
	for (int i = 0; i < n; i++) {
		const ResampleTap &t = taps[i];
		if (t.count < 1 || t.count > maxCount)
			return false;
		int32_t sum = 0;
		for (int j = 0; j < t.count; j++) {
			if (t.weight[j] < 0 || t.weight[j] > kOne)
				return false;
			sum += t.weight[j];
		}
		if (sum > kOne)
			return false;
	}
	return true;
}

// Pair steps the horizontal multiply-add needs: half the most taps, rounded up.
inline int splitSteps(const ResampleTap *xTaps, int dstWidth)
{
	int most = 1;
	for (int x = 0; x < dstWidth; x++)
		most = most > xTaps[x].count ? most : xTaps[x].count;
	return (most + 1) / 2;
}

struct QuadPlan {
	int32_t base;                       // first source byte of the window
	uint8_t index[kSplitMaxSteps][16];  // per pair step: bytes (first, 0, second, 0) per sample
	int16_t weight[kSplitMaxSteps][8];  // per pair step: (w first, w second) per sample
};

// Plans output samples s0..s0+3 of a row (s0 + 4 <= 3 * dstWidth) for a window of
// `window` bytes (indices below it, or kZeroByte). Fails when their taps span more, or
// the row is shorter than the window.
inline bool planQuad(const ResampleTap *xTaps, int s0, int srcW3, int window, QuadPlan &p)
{
	int lo = srcW3, hi = -1;
	for (int k = 0; k < 4; k++) {
		const int x = (s0 + k) / 3, c = (s0 + k) % 3;
		const ResampleTap &t = xTaps[x];
		lo = lo < 3 * t.first + c ? lo : 3 * t.first + c;
		hi = hi > 3 * (t.first + t.count - 1) + c ? hi : 3 * (t.first + t.count - 1) + c;
	}
	if (hi - lo >= window || srcW3 < window)
		return false;
	p.base = lo < srcW3 - window ? lo : srcW3 - window;
	for (int k = 0; k < 4; k++) {
		const int x = (s0 + k) / 3, c = (s0 + k) % 3;
		const ResampleTap &t = xTaps[x];
		for (int step = 0; step < kSplitMaxSteps; step++)
			for (int half = 0; half < 2; half++) {
				const int j = 2 * step + half;
				const bool used = j < t.count;
				p.index[step][4 * k + 2 * half] = used ? uint8_t(3 * (t.first + j) + c - p.base) : kZeroByte;
				p.index[step][4 * k + 2 * half + 1] = kZeroByte;
				p.weight[step][2 * k + half] = used ? int16_t(t.weight[j]) : 0;
			}
	}
	return true;
}

} // namespace
} // namespace kernels
} // namespace calped
