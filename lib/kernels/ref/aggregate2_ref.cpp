// SPDX-License-Identifier: BSD-2-Clause
// Aggregation over 2x2 cells (shrink 2, the Caltech+ and LDCF models), the reference:
// block averages and orientation histograms, with or without the toolbox's spatial
// (trilinear) interpolation.
#include "kernels.h"
#include "fixed_point.h"

#include <cstring>

namespace calped {
namespace kernels {

void shrink2_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *)
{
	const int shift = 2 + extraShift;
	const int w2 = width / 2, h2 = height / 2;
	for (int cy = 0; cy < h2; cy++) {
		const uint16_t *p0 = src + (2 * cy) * srcStride;
		const uint16_t *p1 = p0 + srcStride;
		for (int cx = 0; cx < w2; cx++) {
			const uint32_t acc = uint32_t(p0[2 * cx]) + p0[2 * cx + 1] + p1[2 * cx] + p1[2 * cx + 1];
			dst[cy * dstStride + cx] = static_cast<uint16_t>((acc + (1u << (shift - 1))) >> shift);
		}
	}
}

namespace {

// Pixel x's weight, in quarters, for cell c under the toolbox's bilinear spatial binning
// with bin 2: the pixel sits at (x + 0.5) / 2 - 0.5 in cell units, so cells c with
// x in {2c - 1, 2c, 2c + 1, 2c + 2} take 1, 3, 3, 1 quarters.
inline uint32_t spatialWeight(int x, int c)
{
	const int d = x - 2 * c;
	return (d == 0 || d == 1) ? 3u : ((d == -1 || d == 2) ? 1u : 0u);
}

} // namespace

void gradHist2_ref(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch)
{
	const int w2 = width / 2, h2 = height / 2;
	// scratch as uint64 per orientation and cell of one cell row: the sums of
	// magnitude (Q14) x orientation weight (Q10) x spatial weights (quarters each way).
	uint64_t *acc = reinterpret_cast<uint64_t *>(scratch);
	const int reach = spatial ? 1 : 0;
	for (int cy = 0; cy < h2; cy++) {
		std::memset(acc, 0, sizeof(uint64_t) * nOrients * w2);
		for (int y = 2 * cy - reach; y <= 2 * cy + 1 + reach; y++) {
			if (y < 0 || y >= 2 * h2)
				continue;
			const uint32_t wy = spatial ? spatialWeight(y, cy) : 4u;
			const uint16_t *mrow = mag + y * stride;
			const uint16_t *orow = orient + y * stride;
			for (int x = 0; x < 2 * w2; x++) {
				const uint64_t m = mrow[x];
				const int o = orow[x];
				int o0, o1;
				uint32_t f0, f1;
				if (interpolate) {
					o0 = o >> kOrientQ;
					o1 = o0 + 1 == nOrients ? 0 : o0 + 1;
					f1 = uint32_t(o & ((1 << kOrientQ) - 1));
					f0 = (1u << kOrientQ) - f1;
				} else {
					o0 = (o + (1 << (kOrientQ - 1))) >> kOrientQ;
					if (o0 >= nOrients)
						o0 = 0;
					o1 = o0;
					f0 = 1u << kOrientQ;
					f1 = 0;
				}
				const int cx0 = spatial ? (x + 1) / 2 - 1 : x / 2;
				const int cx1 = spatial ? cx0 + 1 : x / 2;
				for (int cx = cx0; cx <= cx1; cx++) {
					if (cx < 0 || cx >= w2)
						continue;
					const uint64_t w = uint64_t(wy) * (spatial ? spatialWeight(x, cx) : 4u);
					acc[o0 * w2 + cx] += m * f0 * w;
					acc[o1 * w2 + cx] += m * f1 * w;
				}
			}
		}
		// value = acc / (2^10 * 16) / 4 (the toolbox's 1 / bin^2) in Q14: acc / 2^16.
		// With spatial binning the border cells, which lose an eighth of their pixels'
		// weight, are scaled by 8/7 (the corners twice), as the toolbox does.
		const bool borderY = spatial && (cy == 0 || cy == h2 - 1);
		for (int o = 0; o < nOrients; o++) {
			uint16_t *out = hist[o] + cy * histStride;
			for (int cx = 0; cx < w2; cx++) {
				const uint64_t a = acc[o * w2 + cx];
				if (!spatial) {
					out[cx] = saturateU16(int64_t((a + (1u << 15)) >> 16));
					continue;
				}
				const bool borderX = cx == 0 || cx == w2 - 1;
				const uint64_t num = a * (borderY ? 8 : 7) * (borderX ? 8 : 7);
				const uint64_t den = uint64_t(49) << 16;
				out[cx] = saturateU16(int64_t((num + den / 2) / den));
			}
		}
	}
}

} // namespace kernels
} // namespace calped
