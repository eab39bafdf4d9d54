// SPDX-License-Identifier: BSD-2-Clause
// LDCF's decorrelation filter, the reference: Matlab's conv2(C, f, 'same') of one Q14
// channel with a Q15 filter, zero outside the plane, into biased Q12; and one cell of the
// filtered plane resampled to half size, on its own.
#include "kernels.h"
#include "fixed_point.h"

namespace calped {
namespace kernels {

namespace {

// Output (y, x): a convolution, filter tap (a, b) meets sample (y + r - a, x + r - b),
// zero outside the plane; Q14 x Q15 = Q29 sums in 64 bits, down to Q12.
uint16_t filtered(const uint16_t *src, ptrdiff_t stride, int width, int height,
		  const int32_t *filter, int size, int y, int x)
{
	const int r = size / 2;
	int64_t acc = 0;
	for (int a = 0; a < size; a++)
		for (int b = 0; b < size; b++) {
			const int sy = y + r - a, sx = x + r - b;
			if (sy >= 0 && sy < height && sx >= 0 && sx < width)
				acc += int64_t(filter[a * size + b]) * src[sy * stride + sx];
		}
	return saturateU16(shiftRound(acc, kQ + 15 - kLdcfQ) + kLdcfBias);
}

} // namespace

void ldcfFilter_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		    const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride)
{
	for (int y = 0; y < height; y++)
		for (int x = 0; x < width; x++)
			dst[y * dstStride + x] = filtered(src, srcStride, width, height, filter, size, y, x);
}

uint16_t ldcfCell_ref(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		      const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap)
{
	// resamplePlane_ref's two passes for one output: along the rows the taps read, then
	// down the column.
	int64_t acc = 0;
	for (int a = 0; a < yTap.count; a++) {
		int64_t row = 0;
		for (int b = 0; b < xTap.count; b++)
			row += int64_t(xTap.weight[b]) *
			       filtered(plane, stride, width, height, filter.weights, filter.size, yTap.first + a,
				       xTap.first + b);
		acc += int64_t(yTap.weight[a]) * saturateU16(shiftRound(row, kQ));
	}
	return saturateU16(shiftRound(acc, kQ));
}

} // namespace kernels
} // namespace calped
