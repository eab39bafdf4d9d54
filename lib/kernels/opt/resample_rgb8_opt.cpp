// SPDX-License-Identifier: BSD-2-Clause
// RGB8 resampling, portable optimised build (see resample_rgb8_body.h).
#include "opt/resample_rgb8_body.h"

namespace calped {
namespace kernels {

void resampleRgb8_opt(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		      uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		      const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp)
{
	resampleRgb8Body(src, srcStride, srcWidth, srcHeight, dst, dstStride, dstWidth, dstHeight,
			 xTaps, yTaps, rowTmp);
}

} // namespace kernels
} // namespace calped
