// SPDX-License-Identifier: BSD-2-Clause
// LDCF's 5x5 filter with NEON: eight outputs of a row at a time, each sample split into its
// two bytes so that the widening multiply-accumulates (int16 x int16 into int32) sum
// exactly (opt/ldcf_body.h shows why they give the reference's rounding bit for bit). The
// plane's two-cell border, where the filter meets the zeros beyond it, is scalar.
// ldcfCell_neon: one output of the filtered, half-size plane, each full-size value it
// needs as one row of eight samples per filter row (int32 lanes, byte split as above).
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

// The filter at (y, x) of the plane, every sample inside it and samples x - 2 .. x + 5 of
// each row read (x + 5 < width): L and H, the byte sums of opt/ldcf_body.h, over int32
// lanes (below 2^28: 25 x 255 x 2^15), then the reference's rounding and bias.
// first[a]: filter row a reversed (lane k meets sample x - 2 + k); fifth[a]: its last
// tap in lane 0 (sample x + 2).
inline uint16_t filteredAt(const uint16_t *plane, ptrdiff_t stride, int y, int x,
			   const int32x4_t (&first)[kSize], const int32x4_t (&fifth)[kSize])
{
	const uint32x4_t lowByte = vdupq_n_u32(0xFF);
	int32x4_t lo = vdupq_n_s32(0), hi = lo;
	for (int a = 0; a < kSize; a++) {
		const uint16x8_t s = vld1q_u16(plane + (y + kReach - a) * stride + x - kReach);
		const uint32x4_t s0 = vmovl_u16(vget_low_u16(s)), s4 = vmovl_u16(vget_high_u16(s));
		lo = vmlaq_s32(lo, vreinterpretq_s32_u32(vandq_u32(s0, lowByte)), first[a]);
		hi = vmlaq_s32(hi, vreinterpretq_s32_u32(vshrq_n_u32(s0, 8)), first[a]);
		lo = vmlaq_s32(lo, vreinterpretq_s32_u32(vandq_u32(s4, lowByte)), fifth[a]);
		hi = vmlaq_s32(hi, vreinterpretq_s32_u32(vshrq_n_u32(s4, 8)), fifth[a]);
	}
	// Lane sums in uint32 arithmetic (the same bits as int32's).
	const uint32x2_t sums = laneSums2(vreinterpretq_u32_s32(lo), vreinterpretq_u32_s32(hi));
	const int32_t l = int32_t(vget_lane_u32(sums, 0)), h = int32_t(vget_lane_u32(sums, 1));
	return saturateU16(int64_t(ldcf::fromByteSums(h, l)) + kLdcfBias);
}

} // namespace

uint16_t ldcfCell_neon(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const int32_t *filter, int size, const ResampleTap &xTap, const ResampleTap &yTap)
{
	if (!ldcf::cellVectorizable(width, height, size, xTap, yTap))
		return ldcfCell_ref(plane, stride, width, height, filter, size, xTap, yTap);
	int32x4_t first[kSize], fifth[kSize];
	for (int a = 0; a < kSize; a++) {
		const int32_t *f = filter + a * kSize;
		const int32_t lanes[4] = { f[4], f[3], f[2], f[1] };
		first[a] = vld1q_s32(lanes);
		fifth[a] = vsetq_lane_s32(f[0], vdupq_n_s32(0), 0);
	}
	return ldcf::resampledCell(xTap, yTap,
				   [&](int y, int x) { return filteredAt(plane, stride, y, x, first, fifth); });
}

} // namespace kernels
} // namespace calped
