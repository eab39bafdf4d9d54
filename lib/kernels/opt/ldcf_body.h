// SPDX-License-Identifier: BSD-2-Clause
// Shared by the SIMD versions of ldcfFilter (x86/ldcf_avx2.cpp, arm/ldcf_neon.cpp): the
// reference's arithmetic for one output (the plane's border, where the filter meets the
// zeros beyond the plane), which outputs the vector loops cover, and the exact 32-bit
// form of the reference's 64-bit sum that they compute.
//
// The reference sums w * s over the taps in 64 bits (Q15 weights up to 2^15 times Q14
// samples up to 2^16 - 1, 25 of them, overflow 32 bits) and returns
// ((sum + 2^16) >> 17) + bias. With each sample split into bytes, s = 256 hi + lo, the two
// sums H = sum w * hi and L = sum w * lo are below 2^28 in magnitude, and with
// t = H + (L >> 8) (arithmetic shift): sum = 256 t + (L & 255), so
// (sum + 2^16) >> 17 = (t + 256) >> 9 exactly (the low byte never carries into bit 9).
#pragma once

#include <cstddef>
#include <cstdint>

#include "fixed_point.h"
#include "kernels.h"

namespace calped {
namespace kernels {
namespace ldcf {

static_assert(kQ + 15 - kLdcfQ == 17, "the byte split assumes a shift of 17");

// Output (y, x) exactly as ldcfFilter_ref computes it.
inline uint16_t pixel(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		      const int32_t *filter, int size, int y, int x)
{
	const int r = size / 2;
	int64_t acc = 0;
	for (int a = 0; a < size; a++) {
		const int sy = y + r - a;
		if (sy < 0 || sy >= height)
			continue;
		for (int b = 0; b < size; b++) {
			const int sx = x + r - b;
			if (sx >= 0 && sx < width)
				acc += int64_t(filter[a * size + b]) * src[sy * srcStride + sx];
		}
	}
	return saturateU16(shiftRound(acc, kQ + 15 - kLdcfQ) + kLdcfBias);
}

// Whether the vector kernels take this filter: 5 x 5 with every weight an int16 (a weight
// of exactly +1.0, 2^15, would not be; the reference then runs).
inline bool vectorizable(const int32_t *filter, int size)
{
	if (size != 5)
		return false;
	for (int i = 0; i < size * size; i++)
		if (filter[i] < -32768 || filter[i] > 32767)
			return false;
	return true;
}

// The reference's rounding from the two byte sums (see above).
inline int32_t fromByteSums(int32_t hi, int32_t lo) { return (hi + (lo >> 8) + 256) >> 9; }

// ldcfCell's half-size output from the filtered values of the full-size cells its taps
// read (Rows x Columns, the taps' counts): resamplePlane_ref's pass along the row, then
// down the column, each rounded as it rounds them.
template <int Rows, int Columns>
inline uint16_t resampledBlock(const uint16_t (&filtered)[Rows][Columns], const ResampleTap &xTap,
			       const ResampleTap &yTap)
{
	int64_t acc = 0;
#pragma GCC unroll 4
	for (int a = 0; a < Rows; a++) {
		int64_t row = 0;
#pragma GCC unroll 4
		for (int b = 0; b < Columns; b++)
			row += int64_t(xTap.weight[b]) * filtered[a][b];
		acc += int64_t(yTap.weight[a]) * saturateU16(shiftRound(row, kQ));
	}
	return saturateU16(shiftRound(acc, kQ));
}

// Whether ldcfCell's vector versions take this cell: a packed filter, taps that read at
// most four columns and rows, and one row of eight samples from two columns before the
// first full-size cell, of every row the filter reaches, inside the plane.
constexpr int kCellMaxTaps = 4;
inline bool cellVectorizable(int width, int height, const LdcfCellFilter &filter,
			     const ResampleTap &xTap, const ResampleTap &yTap)
{
	return filter.packed && xTap.count >= 1 && xTap.count <= kCellMaxTaps && yTap.count >= 1 &&
	       yTap.count <= kCellMaxTaps && xTap.first >= 2 && xTap.first + 5 < width &&
	       yTap.first >= 2 && yTap.first + yTap.count - 1 + 2 < height;
}

// Every output outside rows [r, height - r) x columns [r, width - r) (where the vector
// loops, which read no sample beyond the plane, do not go), by pixel().
inline void border(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		   const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride)
{
	const int r = size / 2;
	for (int y = 0; y < height; y++) {
		const bool inner = y >= r && y < height - r;
		for (int x = 0; x < width; x++) {
			if (inner && x == r && width - r > r)
				x = width - r; // the inner columns are the vector loops'
			if (x < width)
				dst[y * dstStride + x] = pixel(src, srcStride, width, height, filter, size, y, x);
		}
	}
}

} // namespace ldcf
} // namespace kernels
} // namespace calped
