// SPDX-License-Identifier: BSD-2-Clause
// Gradient magnitude and orientation, the reference (the toolbox's gradMag with
// colorChn 0, then gradMagNorm). Gradients are central differences, one-sided at the
// borders; of the three colour channels the one with the largest squared magnitude
// wins (the first on ties).
#include "kernels.h"
#include "fixed_point.h"

#include <algorithm>
#include <cstdlib>

namespace calped {
namespace kernels {

namespace {

// Twice the toolbox's derivative: I[i+1] - I[i-1] inside, 2 * (one-sided) at the ends.
inline int32_t diff2(const uint16_t *p, ptrdiff_t step, int i, int n)
{
	if (n < 2)
		return 0;
	if (i == 0)
		return 2 * (int32_t(p[step]) - int32_t(p[0]));
	if (i == n - 1)
		return 2 * (int32_t(p[0]) - int32_t(p[-step]));
	return int32_t(p[step]) - int32_t(p[-step]);
}

inline int32_t clampDiff(int32_t v) { return std::clamp(v, -46340, 46340); }

} // namespace

void gradMagOrient_ref(const GradientTables &t, const uint16_t *const planes[3],
		       ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
		       ptrdiff_t outStride, int32_t *)
{
	const int noGradientOrient = t.fromCos[kCosSteps]; // acos(0): the toolbox's pi/2
	for (int y = 0; y < height; y++) {
		for (int x = 0; x < width; x++) {
			int32_t gx = 0, gy = 0;
			uint32_t m2 = 0; // (2 |G|)^2 in Q32
			for (int c = 0; c < 3; c++) {
				const uint16_t *p = planes[c] + y * stride + x;
				const int32_t cx = clampDiff(diff2(p, 1, x, width));
				const int32_t cy = clampDiff(diff2(p, stride, y, height));
				const uint32_t cm2 = uint32_t(cx * cx) + uint32_t(cy * cy);
				if (c == 0 || cm2 > m2) {
					m2 = cm2;
					gx = cx;
					gy = cy;
				}
			}
			uint16_t *mo = mag + y * outStride + x;
			uint16_t *oo = orient + y * outStride + x;
			if (m2 == 0) {
				*mo = 0;
				*oo = static_cast<uint16_t>(noGradientOrient);
				continue;
			}
			int m, k;
			normalizeEven(m2, m, k);
			// |G| = sqrt(m2) / 2 in Q16.
			*mo = saturateU16(shiftRound(int64_t(t.sqrtQ8[m]) << (k / 2), 9));
			// Cosine of the orientation folded into [0, pi) (gx flips with gy's sign), as
			// the toolbox's acos index: gx * rsqrt(m2) * 10000 truncated toward zero.
			const int64_t p = int64_t(gy < 0 ? -gx : gx) * t.rsqrtQ20[m]; // cos * 2^(20 + k/2)
			const int64_t c = ((p < 0 ? -p : p) * kCosSteps) >> (20 + k / 2);
			*oo = t.fromCos[std::min<int64_t>(c, kCosSteps) * (p < 0 ? -1 : 1) + kCosSteps];
		}
	}
}

void normalizeMag_ref(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		      const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height)
{
	for (int y = 0; y < height; y++) {
		uint16_t *mrow = mag + y * magStride;
		const uint32_t *srow = smoothedSum + y * sumStride;
		for (int x = 0; x < width; x++) {
			const uint64_t d = uint64_t(srow[x]) + t.normConst;
			if (d == 0) {
				mrow[x] = 0;
				continue;
			}
			int m, k;
			normalize12(d, m, k);
			// normRcp = (r+1)^4 * 2^16 / m and M is Q16, so M * normRcp / 2^(k+2) is
			// M / (d / (r+1)^4) in Q14.
			mrow[x] = saturateU16(shiftRound(int64_t(mrow[x]) * t.normRcp[m - 2048], k + 2));
		}
	}
}

} // namespace kernels
} // namespace calped
