// SPDX-License-Identifier: BSD-2-Clause
// Orientation histograms, portable optimised build (see hist_body.h).
#include "opt/hist_body.h"

namespace calped {
namespace kernels {

void gradHist4_opt(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch)
{
	gradHist4Body(mag, orient, stride, width, height, nOrients, interpolate, hist, histStride,
		      scratch);
}

} // namespace kernels
} // namespace calped
