// SPDX-License-Identifier: BSD-2-Clause
// The portable optimised kernels compiled with AVX2: the same source bodies as opt/
// (bit-identical by construction and by test), vectorised by the compiler with 256-bit
// integer operations (32-bit multiplies need SSE4.1 or better, which the baseline build
// cannot assume).
#include "opt/hist2_body.h"
#include "opt/hist_body.h"

namespace calped {
namespace kernels {

void shrink4_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch)
{
	shrink4Body(src, srcStride, width, height, dst, dstStride, extraShift, scratch);
}

// The rows of per-pixel contributions vectorise; shrink2 has its own (aggregate2_avx2.cpp).
void gradHist2_avx2(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist2Body(mag, orient, stride, width, height, nOrients, interpolate, spatial, hist,
		      histStride, scratch);
}

} // namespace kernels
} // namespace calped
