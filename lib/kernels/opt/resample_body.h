// SPDX-License-Identifier: BSD-2-Clause
// Body of the optimised plane resampling, shared by the portable build (opt/) and the
// SIMD builds (x86/), which compile it with their own instruction sets. Internal
// linkage: each translation unit keeps its own copy. Bit-identical to
// ref/resample_ref.cpp: 32-bit accumulators suffice because weights are non-negative
// and sum to at most gain * 2^14.
#pragma once

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

inline uint16_t roundQ14(uint32_t acc)
{
	const uint32_t v = (acc + (1u << (kQ - 1))) >> kQ;
	return static_cast<uint16_t>(v > 65535 ? 65535 : v);
}

// The column pass: tmp (rows already resampled) to dst, a whole row at a time.
inline void resampleColumnsBody(uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
				const ResampleTap *yTaps, const uint16_t *tmp, ptrdiff_t tmpStride)
{
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &t = yTaps[y];
		uint16_t *out = dst + y * dstStride;
		const uint16_t *r0 = tmp + t.first * tmpStride;
		const uint32_t w0 = uint32_t(t.weight[0]);
		if (t.count == 1) {
			for (int x = 0; x < dstWidth; x++)
				out[x] = roundQ14(w0 * r0[x]);
		} else if (t.count == 2) {
			const uint16_t *r1 = r0 + tmpStride;
			const uint32_t w1 = uint32_t(t.weight[1]);
			for (int x = 0; x < dstWidth; x++)
				out[x] = roundQ14(w0 * r0[x] + w1 * r1[x]);
		} else if (t.count == 3) {
			const uint16_t *r1 = r0 + tmpStride, *r2 = r1 + tmpStride;
			const uint32_t w1 = uint32_t(t.weight[1]), w2 = uint32_t(t.weight[2]);
			for (int x = 0; x < dstWidth; x++)
				out[x] = roundQ14(w0 * r0[x] + w1 * r1[x] + w2 * r2[x]);
		} else {
			for (int x = 0; x < dstWidth; x++) {
				uint32_t acc = 0;
				for (int j = 0; j < t.count; j++)
					acc += uint32_t(t.weight[j]) * r0[j * tmpStride + x];
				out[x] = roundQ14(acc);
			}
		}
	}
}

inline void resamplePlaneBody(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
		       ptrdiff_t tmpStride)
{
	// Along rows. Outputs of at most three taps (enlarging, and shrinking by up to 2x,
	// which is every use in the pyramid) take a fixed three-tap form: a missing tap
	// reads the first sample again with weight 0, so no read leaves the row.
	bool threeTaps = true, halving = true;
	for (int x = 0; x < dstWidth && threeTaps; x++) {
		const ResampleTap &t = xTaps[x];
		threeTaps = t.count <= 3;
		halving = halving && t.count == 2 && t.first == 2 * x && t.weight[0] == kOne / 2 &&
			  t.weight[1] == kOne / 2;
	}
	if (halving) {
		// Exactly half the width (the computed octaves): (a + b + 1) / 2, row by row.
		for (int y = 0; y < srcHeight; y++) {
			const uint16_t *in = src + y * srcStride;
			uint16_t *out = tmp + y * tmpStride;
			for (int x = 0; x < dstWidth; x++)
				out[x] = static_cast<uint16_t>((uint32_t(in[2 * x]) + in[2 * x + 1] + 1) >> 1);
		}
	} else if (threeTaps) {
		// Column by column: each tap is decoded once for all rows.
		for (int x = 0; x < dstWidth; x++) {
			const ResampleTap &t = xTaps[x];
			const int n = t.count;
			const uint32_t w0 = uint32_t(t.weight[0]);
			const uint32_t w1 = n > 1 ? uint32_t(t.weight[1]) : 0;
			const uint32_t w2 = n > 2 ? uint32_t(t.weight[2]) : 0;
			const int o1 = n > 1 ? 1 : 0, o2 = n > 2 ? 2 : 0;
			const uint16_t *in = src + t.first;
			uint16_t *out = tmp + x;
			for (int y = 0; y < srcHeight; y++, in += srcStride, out += tmpStride)
				*out = roundQ14(w0 * in[0] + w1 * in[o1] + w2 * in[o2]);
		}
	} else {
		for (int y = 0; y < srcHeight; y++) {
			const uint16_t *in = src + y * srcStride;
			uint16_t *out = tmp + y * tmpStride;
			for (int x = 0; x < dstWidth; x++) {
				const ResampleTap &t = xTaps[x];
				const uint16_t *p = in + t.first;
				uint32_t acc = 0;
				for (int j = 0; j < t.count; j++)
					acc += uint32_t(t.weight[j]) * p[j];
				out[x] = roundQ14(acc);
			}
		}
	}
	(void)srcWidth;
	resampleColumnsBody(dst, dstStride, dstWidth, dstHeight, yTaps, tmp, tmpStride);
}

} // namespace
} // namespace kernels
} // namespace calped
