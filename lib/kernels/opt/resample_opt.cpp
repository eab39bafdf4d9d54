// SPDX-License-Identifier: BSD-2-Clause
// Plane resampling, portable optimised build (see resample_body.h).
#include "opt/resample_body.h"

namespace calped {
namespace kernels {

void resamplePlane_opt(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
		       ptrdiff_t tmpStride)
{
	resamplePlaneBody(src, srcStride, srcWidth, srcHeight, dst, dstStride, dstWidth, dstHeight,
			  xTaps, yTaps, tmp, tmpStride);
}

void resamplePlanes_opt(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			ptrdiff_t tmpStride)
{
	resampleEachPlane<resamplePlane_opt>(jobs, count, srcWidth, srcHeight, dstWidth, dstHeight,
					     xTaps, tmp, tmpStride);
}

} // namespace kernels
} // namespace calped
