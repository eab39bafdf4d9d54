// SPDX-License-Identifier: BSD-2-Clause
// Body of the optimised RGB8 resampling (the input "resize"), shared by the portable and
// SIMD builds. Bit-identical to ref/resample_ref.cpp. When every weight is a multiple of
// a power of two (2x enlarging: quarters of 2^14), the weights are divided by it and the
// sums fit 32 bits, so the column pass vectorises; otherwise sums are 64-bit.
#pragma once

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

// Largest s such that every weight of every tap is a multiple of 2^s (at most 14).
inline int commonWeightShift(const ResampleTap *taps, int n)
{
	int s = 14;
	for (int i = 0; i < n; i++)
		for (int j = 0; j < taps[i].count; j++)
			s = std::min(s, taps[i].weight[j] ? __builtin_ctz(uint32_t(taps[i].weight[j])) : 14);
	return s;
}

// Whether the taps are the toolbox's exact 2x enlargement: every output between two
// inputs at weights 1/4 and 3/4, the two outer ones copies.
inline bool isDoubling(const ResampleTap *taps, int n, int m)
{
	if (m != 2 * n || n < 2)
		return false;
	const int q = kOne / 4;
	if (taps[0].count != 1 || taps[0].first != 0 || taps[m - 1].count != 1 ||
	    taps[m - 1].first != n - 1)
		return false;
	for (int i = 1; i < n; i++) {
		const ResampleTap &e = taps[2 * i], &o = taps[2 * i - 1];
		if (e.count != 2 || e.first != i - 1 || e.weight[0] != q || e.weight[1] != 3 * q ||
		    o.count != 2 || o.first != i - 1 || o.weight[0] != 3 * q || o.weight[1] != q)
			return false;
	}
	return true;
}

inline void resampleRgb8Body(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			     uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			     const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp)
{
	(void)srcHeight;
	const int sy = commonWeightShift(yTaps, dstHeight);
	// Keep at least one bit to shift out, so halves can round down.
	const int sx = std::min(commonWeightShift(xTaps, dstWidth), 27 - sy);
	// With weights divided by 2^(sx+sy), the sums are below 255 * 2^(28 - sx - sy).
	const bool small = 28 - sx - sy <= 22;
	const int shift = small ? 28 - sx - sy : 28;
	const int64_t bias = (int64_t(1) << (shift - 1)) - 1; // halves round down
	const int srcW3 = 3 * srcWidth;
	bool twoTaps = true;
	for (int x = 0; x < dstWidth && twoTaps; x++)
		twoTaps = xTaps[x].count <= 2;
	const bool doubling = isDoubling(xTaps, srcWidth, dstWidth);
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		const int ySh = small ? sy : 0;
		const uint8_t *r0 = src + ty.first * srcStride;
		const int32_t w0 = ty.weight[0] >> ySh;
		if (ty.count == 1) {
			for (int i = 0; i < srcW3; i++)
				rowTmp[i] = w0 * r0[i];
		} else {
			const uint8_t *r1 = r0 + srcStride;
			const int32_t w1 = ty.weight[1] >> ySh;
			for (int i = 0; i < srcW3; i++)
				rowTmp[i] = w0 * r0[i] + w1 * r1[i];
			for (int j = 2; j < ty.count; j++) {
				const uint8_t *rj = r0 + j * srcStride;
				const int32_t wj = ty.weight[j] >> ySh;
				for (int i = 0; i < srcW3; i++)
					rowTmp[i] += wj * rj[i];
			}
		}
		uint8_t *out = dst + y * dstStride;
		const int xSh = small ? sx : 0;
		if (small && doubling) {
			// out = (a + 3 b) or (3 b + c) scaled: whole pixels, in a loop of fixed shape.
			const int32_t b32 = int32_t(bias);
			const int32_t q = (kOne / 4) >> xSh;
			auto put = [&](uint8_t *o, int32_t v) {
				v >>= shift;
				*o = static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
			};
			for (int c = 0; c < 3; c++) {
				put(out + c, 4 * q * rowTmp[c] + b32);
				put(out + 3 * (dstWidth - 1) + c, 4 * q * rowTmp[3 * (srcWidth - 1) + c] + b32);
			}
			for (int i = 1; i < srcWidth; i++) {
				const int32_t *a = rowTmp + 3 * (i - 1), *b = a + 3;
				uint8_t *odd = out + 3 * (2 * i - 1), *even = out + 3 * (2 * i);
				for (int c = 0; c < 3; c++) {
					put(odd + c, 3 * q * a[c] + q * b[c] + b32);
					put(even + c, q * a[c] + 3 * q * b[c] + b32);
				}
			}
			continue;
		}
		if (small && twoTaps) {
			// 32-bit sums of at most two taps: a missing second tap reads the first
			// pixel again with weight 0.
			const int32_t b32 = int32_t(bias);
			for (int x = 0; x < dstWidth; x++) {
				const ResampleTap &tx = xTaps[x];
				const int32_t *p = rowTmp + 3 * tx.first;
				const int32_t w0 = tx.weight[0] >> xSh;
				const int32_t w1 = tx.count > 1 ? tx.weight[1] >> xSh : 0;
				const int32_t *q = tx.count > 1 ? p + 3 : p;
				for (int c = 0; c < 3; c++) {
					const int32_t v = (w0 * p[c] + w1 * q[c] + b32) >> shift;
					out[3 * x + c] = static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
				}
			}
			continue;
		}
		for (int x = 0; x < dstWidth; x++) {
			const ResampleTap &tx = xTaps[x];
			const int32_t *p = rowTmp + 3 * tx.first;
			int64_t a0 = 0, a1 = 0, a2 = 0;
			for (int j = 0; j < tx.count; j++) {
				const int64_t w = tx.weight[j] >> xSh;
				a0 += w * p[3 * j];
				a1 += w * p[3 * j + 1];
				a2 += w * p[3 * j + 2];
			}
			out[3 * x] = static_cast<uint8_t>(std::clamp<int64_t>((a0 + bias) >> shift, 0, 255));
			out[3 * x + 1] = static_cast<uint8_t>(std::clamp<int64_t>((a1 + bias) >> shift, 0, 255));
			out[3 * x + 2] = static_cast<uint8_t>(std::clamp<int64_t>((a2 + bias) >> shift, 0, 255));
		}
	}
}

} // namespace
} // namespace kernels
} // namespace calped
