// SPDX-License-Identifier: BSD-2-Clause
// 4x4 and 2x2 aggregation, portable optimised build (see hist_body.h, hist2_body.h).
#include "opt/hist2_body.h"
#include "opt/hist_body.h"

namespace calped {
namespace kernels {

void shrink4_opt(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch)
{
	shrink4Body(src, srcStride, width, height, dst, dstStride, extraShift, scratch);
}

void gradHist4_opt(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist4Body(mag, orient, stride, width, height, nOrients, interpolate, hist, histStride,
		      scratch);
}

void shrink2_opt(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	shrink2Body(src, srcStride, width, height, dst, dstStride, extraShift);
}

void gradHist2_opt(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist2Body(mag, orient, stride, width, height, nOrients, interpolate, spatial, hist,
		      histStride, scratch);
}

} // namespace kernels
} // namespace calped
