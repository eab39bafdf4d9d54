// SPDX-License-Identifier: BSD-2-Clause
// Triangle smoothing, portable optimised build (see smooth_body.h).
#include "opt/smooth_body.h"

namespace calped {
namespace kernels {

void smoothTri1_opt(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		    ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp)
{
	smoothTri1Body(src, srcStride, dst, dstStride, width, height, rowTmp);
}

void triSumR_opt(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		 int width, int height, int r, uint32_t *scratch)
{
	triSumRBody(src, srcStride, dst, dstStride, width, height, r, scratch);
}

} // namespace kernels
} // namespace calped
