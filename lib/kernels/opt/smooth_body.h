// SPDX-License-Identifier: BSD-2-Clause
// Bodies of the optimised triangle smoothing kernels, shared by the portable build (opt/)
// and the SIMD builds (x86/), which compile them with their own instruction sets.
// Internal linkage: each translation unit keeps its own copy. Whole rows at a time with
// the borders outside the inner loops, so compilers vectorise them. Bit-identical to
// ref/smooth_ref.cpp.
#pragma once

#include <algorithm>

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

inline void smoothTri1Body(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		    ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp)
{
	for (int y = 0; y < height; y++) {
		const uint16_t *a = src + std::max(y - 1, 0) * srcStride;
		const uint16_t *b = src + y * srcStride;
		const uint16_t *c = src + std::min(y + 1, height - 1) * srcStride;
		for (int x = 0; x < width; x++)
			rowTmp[x] = uint32_t(a[x]) + 2 * uint32_t(b[x]) + uint32_t(c[x]);
		uint16_t *out = dst + y * dstStride;
		if (width == 1) {
			out[0] = static_cast<uint16_t>((4 * rowTmp[0] + 8) >> 4);
			continue;
		}
		out[0] = static_cast<uint16_t>((3 * rowTmp[0] + rowTmp[1] + 8) >> 4);
		for (int x = 1; x < width - 1; x++)
			out[x] = static_cast<uint16_t>((rowTmp[x - 1] + 2 * rowTmp[x] + rowTmp[x + 1] + 8) >> 4);
		out[width - 1] =
			static_cast<uint16_t>((rowTmp[width - 2] + 3 * rowTmp[width - 1] + 8) >> 4);
	}
}

inline int reflect(int i, int n)
{
	while (i < 0 || i >= n) {
		if (i < 0)
			i = -i - 1;
		if (i >= n)
			i = 2 * n - i - 1;
	}
	return i;
}

// 1-D triangle sum of q[0 .. n + 2r) (already padded) into out[0 .. n): two running
// box sums of r + 1 samples, whose composition is the triangle 1..r+1..1.
inline void triangleRow(const uint32_t *q, int n, int r, uint32_t *box, uint32_t *out)
{
	uint32_t acc = 0;
	for (int j = 0; j < r; j++)
		acc += q[j];
	for (int m = 0; m < n + r; m++) {
		acc += q[m + r];
		box[m] = acc;
		acc -= q[m];
	}
	uint32_t acc2 = 0;
	for (int j = 0; j < r; j++)
		acc2 += box[j];
	for (int y = 0; y < n; y++) {
		acc2 += box[y + r];
		out[y] = acc2;
		acc2 -= box[y];
	}
}

// Where triSumRBody keeps its intermediate rows in the scratch of triSumScratchSize: the
// horizontal result (width x height), then one padded row, one box row, the ring of r + 1
// box rows and two accumulator rows.
struct TriSumScratch {
	uint32_t *horiz, *padded, *boxRow, *ring, *acc1, *acc2;
	TriSumScratch(uint32_t *scratch, int width, int height, int r)
	{
		horiz = scratch;
		padded = horiz + size_t(width) * height;
		boxRow = padded + width + 2 * r;
		ring = boxRow + width + r;
		acc1 = ring + size_t(r + 1) * width;
		acc2 = acc1 + width;
	}
};

// Row y of src with r samples of symmetric padding on each side: padded[0 .. width + 2r).
inline void padRow(const uint16_t *row, int width, int r, uint32_t *padded)
{
	for (int i = 0; i < r; i++) {
		padded[i] = row[reflect(i - r, width)];
		padded[width + r + i] = row[reflect(width + i, width)];
	}
	for (int x = 0; x < width; x++)
		padded[r + x] = row[x];
}

// Row m of the horizontal result padded by r rows of symmetric padding at each end.
inline const uint32_t *triSumPaddedRow(const TriSumScratch &s, int m, int width, int height, int r)
{
	return s.horiz + size_t(reflect(m - r, height)) * width;
}

// The vertical pass's start: acc2 empty, acc1 holding the first r padded rows.
inline void triSumColumnsStart(const TriSumScratch &s, int width, int height, int r)
{
	for (int x = 0; x < width; x++)
		s.acc1[x] = s.acc2[x] = 0;
	for (int j = 0; j < r; j++) {
		const uint32_t *qj = triSumPaddedRow(s, j, width, height, r);
		for (int x = 0; x < width; x++)
			s.acc1[x] += qj[x];
	}
}

// The vertical pass: the same two running sums as triangleRow, a column per lane, over
// whole rows of the horizontal result s.horiz, into dst.
inline void triSumColumnsBody(const TriSumScratch &s, uint32_t *dst, ptrdiff_t dstStride,
			      int width, int height, int r)
{
	auto q = [&](int m) { return triSumPaddedRow(s, m, width, height, r); };
	uint32_t *acc1 = s.acc1, *acc2 = s.acc2;
	triSumColumnsStart(s, width, height, r);
	for (int m = 0; m < height + r; m++) {
		const uint32_t *in = q(m + r);
		const uint32_t *leaving = q(m);
		uint32_t *box = s.ring + size_t(m % (r + 1)) * width;
		for (int x = 0; x < width; x++) {
			acc1[x] += in[x];
			box[x] = acc1[x];
			acc2[x] += acc1[x];
			acc1[x] -= leaving[x];
		}
		if (m >= r) {
			const int y = m - r;
			uint32_t *out = dst + y * dstStride;
			const uint32_t *oldest = s.ring + size_t(y % (r + 1)) * width;
			for (int x = 0; x < width; x++) {
				out[x] = acc2[x];
				acc2[x] -= oldest[x];
			}
		}
	}
}

inline void triSumRBody(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		 int width, int height, int r, uint32_t *scratch)
{
	const TriSumScratch s(scratch, width, height, r);
	for (int y = 0; y < height; y++) {
		padRow(src + y * srcStride, width, r, s.padded);
		triangleRow(s.padded, width, r, s.boxRow, s.horiz + size_t(y) * width);
	}
	triSumColumnsBody(s, dst, dstStride, width, height, r);
}

} // namespace
} // namespace kernels
} // namespace calped
