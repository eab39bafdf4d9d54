// SPDX-License-Identifier: BSD-2-Clause
// Separable resampling with precomputed taps, the reference (the toolbox's
// imResampleMex: rows first, then columns).
#include "kernels.h"
#include "fixed_point.h"

namespace calped {
namespace kernels {

void resampleRgb8_ref(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		      uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		      const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp)
{
	(void)srcWidth;
	(void)srcHeight;
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		// Column pass first for this output row: rowTmp = sum_j wy_j * src row (Q14).
		const int srcW3 = 3 * srcWidth;
		for (int i = 0; i < srcW3; i++) {
			int32_t acc = 0;
			for (int j = 0; j < ty.count; j++)
				acc += ty.weight[j] * src[(ty.first + j) * srcStride + i];
			rowTmp[i] = acc;
		}
		uint8_t *out = dst + y * dstStride;
		for (int x = 0; x < dstWidth; x++) {
			const ResampleTap &tx = xTaps[x];
			for (int c = 0; c < 3; c++) {
				int64_t acc = 0;
				for (int j = 0; j < tx.count; j++)
					acc += int64_t(tx.weight[j]) * rowTmp[3 * (tx.first + j) + c];
				// Q28 -> 8 bits; exact halves round down like the toolbox.
				const int64_t v = (acc + (int64_t(1) << 27) - 1) >> 28;
				out[3 * x + c] = static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
			}
		}
	}
}

void resamplePlane_ref(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
		       ptrdiff_t tmpStride)
{
	(void)srcWidth;
	// Along rows: every source row to dstWidth samples (Q14, rounded).
	for (int y = 0; y < srcHeight; y++) {
		const uint16_t *in = src + y * srcStride;
		uint16_t *out = tmp + y * tmpStride;
		for (int x = 0; x < dstWidth; x++) {
			const ResampleTap &tx = xTaps[x];
			int64_t acc = 0;
			for (int j = 0; j < tx.count; j++)
				acc += int64_t(tx.weight[j]) * in[tx.first + j];
			out[x] = saturateU16(shiftRound(acc, kQ));
		}
	}
	// Along columns, with the level's gain folded into the weights.
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		uint16_t *out = dst + y * dstStride;
		for (int x = 0; x < dstWidth; x++) {
			int64_t acc = 0;
			for (int j = 0; j < ty.count; j++)
				acc += int64_t(ty.weight[j]) * tmp[(ty.first + j) * tmpStride + x];
			out[x] = saturateU16(shiftRound(acc, kQ));
		}
	}
}

void resamplePlanes_ref(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			ptrdiff_t tmpStride)
{
	resampleEachPlane<resamplePlane_ref>(jobs, count, srcWidth, srcHeight, dstWidth, dstHeight,
					     xTaps, tmp, tmpStride);
}

} // namespace kernels
} // namespace calped
