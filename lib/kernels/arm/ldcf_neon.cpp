// SPDX-License-Identifier: BSD-2-Clause
// LDCF's 5x5 filter with NEON: eight outputs of a row at a time, each sample split into its
// two bytes so that the widening multiply-accumulates (int16 x int16 into int32) sum
// exactly (opt/ldcf_body.h shows why they give the reference's rounding bit for bit). The
// plane's two-cell border, where the filter meets the zeros beyond it, is scalar.
// ldcfCell_neon: one output of the filtered, half-size plane from a block of the full-size
// values it needs, computed together from one load of each plane row they read.
#include <arm_neon.h>

#include <algorithm>

#include "arm/neon_util.h"
#include "opt/ldcf_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kSize = 5, kReach = 2;

// Eight outputs (y, x0 .. x0 + 7), all of whose samples lie inside the plane.
inline void block8(const uint16_t *src, ptrdiff_t srcStride, int y, int x0, const int16_t *w,
		   uint16_t *dst)
{
	const uint16x8_t lowByte = vdupq_n_u16(0x00FF);
	int32x4_t loA = vdupq_n_s32(0), loB = loA, hiA = loA, hiB = loA;
	for (int a = 0; a < kSize; a++) {
		// Tap (a, b) meets sample (y + 2 - a, x + 2 - b).
		const uint16_t *p = src + (y + kReach - a) * srcStride + x0 + kReach;
		for (int b = 0; b < kSize; b++) {
			const uint16x8_t s = vld1q_u16(p - b);
			const int16x8_t lo = vreinterpretq_s16_u16(vandq_u16(s, lowByte));
			const int16x8_t hi = vreinterpretq_s16_u16(vshrq_n_u16(s, 8));
			const int16_t wt = w[a * kSize + b];
			loA = vmlal_n_s16(loA, vget_low_s16(lo), wt);
			loB = vmlal_n_s16(loB, vget_high_s16(lo), wt);
			hiA = vmlal_n_s16(hiA, vget_low_s16(hi), wt);
			hiB = vmlal_n_s16(hiB, vget_high_s16(hi), wt);
		}
	}
	// ldcf::fromByteSums, then the bias, saturated to [0, 65535] like the reference.
	const int32x4_t round = vdupq_n_s32(256), bias = vdupq_n_s32(kLdcfBias);
	const int32x4_t a = vaddq_s32(vshrq_n_s32(vaddq_s32(vaddq_s32(hiA, vshrq_n_s32(loA, 8)), round), 9), bias);
	const int32x4_t b = vaddq_s32(vshrq_n_s32(vaddq_s32(vaddq_s32(hiB, vshrq_n_s32(loB, 8)), round), 9), bias);
	vst1q_u16(dst, vcombine_u16(vqmovun_s32(a), vqmovun_s32(b)));
}

} // namespace

void ldcfFilter_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		     const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride)
{
	if (!ldcf::vectorizable(filter, size)) {
		ldcfFilter_ref(src, srcStride, width, height, filter, size, dst, dstStride);
		return;
	}
	int16_t w[kSize * kSize];
	for (int i = 0; i < kSize * kSize; i++)
		w[i] = int16_t(filter[i]);
	ldcf::border(src, srcStride, width, height, filter, size, dst, dstStride);
	const int inner = width - 2 * kReach;
	for (int y = kReach; y < height - kReach; y++) {
		uint16_t *out = dst + y * dstStride;
		if (inner < 8) {
			for (int x = kReach; x < width - kReach; x++)
				out[x] = ldcf::pixel(src, srcStride, width, height, filter, size, y, x);
			continue;
		}
		// The last block ends at the inner columns' end, overlapping the one before.
		for (int x0 = kReach;; x0 += 8) {
			x0 = std::min(x0, width - kReach - 8);
			block8(src, srcStride, y, x0, w, out + x0);
			if (x0 == width - kReach - 8)
				break;
		}
	}
}

namespace {

// The cell whose taps read full-size cells (y0 + r, x0 + j), r < Rows, j < Columns, every
// sample they need inside the plane. Their filtered values come from one load of each
// plane row they reach, eight samples from x0 - 2, split into bytes and multiplied lane by
// lane with the packed taps of each output column: L and H of opt/ldcf_body.h in int32
// lanes (below 2^28), then its rounding and the bias; then the taps.
template <int Rows, int Columns>
uint16_t cell(const uint16_t *plane, ptrdiff_t stride, const int16_t *packed, const ResampleTap &xTap,
	      const ResampleTap &yTap)
{
	const int y0 = yTap.first, x0 = xTap.first;
	const uint16x8_t lowByte = vdupq_n_u16(0x00FF);
	int32x4_t lo[Rows][Columns], hi[Rows][Columns];
#pragma GCC unroll 4
	for (int r = 0; r < Rows; r++)
#pragma GCC unroll 4
		for (int j = 0; j < Columns; j++)
			lo[r][j] = hi[r][j] = vdupq_n_s32(0);
#pragma GCC unroll 8
	for (int i = 0; i < Rows + 4; i++) {
		const uint16x8_t s = vld1q_u16(plane + (y0 - kReach + i) * stride + x0 - kReach);
		const int16x8_t sLo = vreinterpretq_s16_u16(vandq_u16(s, lowByte));
		const int16x8_t sHi = vreinterpretq_s16_u16(vshrq_n_u16(s, 8));
		// Plane row y0 - 2 + i meets filter row a = r + 4 - i of output row r.
#pragma GCC unroll 4
		for (int r = 0; r < Rows; r++) {
			const int a = r + 4 - i;
			if (a < 0 || a > 4)
				continue;
#pragma GCC unroll 4
			for (int j = 0; j < Columns; j++) {
				const int16x8_t w = vld1q_s16(packed + (a * 4 + j) * 8);
				lo[r][j] = vmlal_s16(lo[r][j], vget_low_s16(sLo), vget_low_s16(w));
				lo[r][j] = vmlal_s16(lo[r][j], vget_high_s16(sLo), vget_high_s16(w));
				hi[r][j] = vmlal_s16(hi[r][j], vget_low_s16(sHi), vget_low_s16(w));
				hi[r][j] = vmlal_s16(hi[r][j], vget_high_s16(sHi), vget_high_s16(w));
			}
		}
	}
	// Lane sums two outputs at a time, in uint32 arithmetic (the same bits as int32's).
	constexpr int kCount = Rows * Columns;
	uint16_t filtered[Rows][Columns];
#pragma GCC unroll 8
	for (int n = 0; n < kCount; n += 2) {
		const int m = std::min(n + 1, kCount - 1);
		const uint32x4_t sums = horizontalSums4(
			vreinterpretq_u32_s32(lo[n / Columns][n % Columns]), vreinterpretq_u32_s32(hi[n / Columns][n % Columns]),
			vreinterpretq_u32_s32(lo[m / Columns][m % Columns]), vreinterpretq_u32_s32(hi[m / Columns][m % Columns]));
		filtered[n / Columns][n % Columns] = saturateU16(
			int64_t(ldcf::fromByteSums(int32_t(vgetq_lane_u32(sums, 1)), int32_t(vgetq_lane_u32(sums, 0)))) + kLdcfBias);
		filtered[m / Columns][m % Columns] = saturateU16(
			int64_t(ldcf::fromByteSums(int32_t(vgetq_lane_u32(sums, 3)), int32_t(vgetq_lane_u32(sums, 2)))) + kLdcfBias);
	}
	return ldcf::resampledBlock(filtered, xTap, yTap);
}

using CellFn = uint16_t (*)(const uint16_t *, ptrdiff_t, const int16_t *, const ResampleTap &,
			    const ResampleTap &);
constexpr CellFn kCells[4][4] = {
	{ cell<1, 1>, cell<1, 2>, cell<1, 3>, cell<1, 4> },
	{ cell<2, 1>, cell<2, 2>, cell<2, 3>, cell<2, 4> },
	{ cell<3, 1>, cell<3, 2>, cell<3, 3>, cell<3, 4> },
	{ cell<4, 1>, cell<4, 2>, cell<4, 3>, cell<4, 4> },
};

} // namespace

uint16_t ldcfCell_neon(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap)
{
	if (!ldcf::cellVectorizable(width, height, filter, xTap, yTap))
		return ldcfCell_ref(plane, stride, width, height, filter, xTap, yTap);
	return kCells[yTap.count - 1][xTap.count - 1](plane, stride, filter.packed, xTap, yTap);
}

} // namespace kernels
} // namespace calped
