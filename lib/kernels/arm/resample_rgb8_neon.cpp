// SPDX-License-Identifier: BSD-2-Clause
// RGB8 resampling with NEON for the toolbox's exact 2x enlargement (the input "resize 2"):
// the column pass eight bytes at a time, then each pair of neighbouring input pixels
// a, b gives the outputs (3a + b) / 4 and (a + 3b) / 4, eight pairs of pixels at a time
// with de-interleaving loads and an interleaving store. Weights are divided by their
// common power of two as in the portable body (opt/resample_rgb8_body.h), so the sums
// fit 32 bits; bit-identical to ref/resample_ref.cpp. Other ratios use the portable
// kernel.
#include <arm_neon.h>

#include "opt/resample_rgb8_body.h"

namespace calped {
namespace kernels {

namespace {

// rowTmp[i] = sum over j of weight_j * row_j[i], weights already divided by 2^ySh.
void columnPass(const uint8_t *r0, ptrdiff_t srcStride, const ResampleTap &t, int ySh, int n,
		int32_t *rowTmp)
{
	int i = 0;
	for (; i + 8 <= n; i += 8) {
		int32x4_t lo = vdupq_n_s32(0), hi = vdupq_n_s32(0);
		for (int j = 0; j < t.count; j++) {
			const uint16x8_t v = vmovl_u8(vld1_u8(r0 + j * srcStride + i));
			const int32_t w = t.weight[j] >> ySh;
			lo = vmlaq_n_s32(lo, vreinterpretq_s32_u32(vmovl_u16(vget_low_u16(v))), w);
			hi = vmlaq_n_s32(hi, vreinterpretq_s32_u32(vmovl_u16(vget_high_u16(v))), w);
		}
		vst1q_s32(rowTmp + i, lo);
		vst1q_s32(rowTmp + i + 4, hi);
	}
	for (; i < n; i++) {
		int32_t acc = 0;
		for (int j = 0; j < t.count; j++)
			acc += (t.weight[j] >> ySh) * r0[j * srcStride + i];
		rowTmp[i] = acc;
	}
}

// (v + bias) >> shift per lane, clamped to 0..255, eight lanes.
inline uint8x8_t toByte(int32x4_t lo, int32x4_t hi, int32x4_t bias, int32x4_t right)
{
	lo = vshlq_s32(vaddq_s32(lo, bias), right);
	hi = vshlq_s32(vaddq_s32(hi, bias), right);
	return vqmovn_u16(vcombine_u16(vqmovun_s32(lo), vqmovun_s32(hi)));
}

} // namespace

void resampleRgb8_neon(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp)
{
	// The portable body's scaling: weights divided by 2^(sx + sy), sums below 2^30.
	const int sy = commonWeightShift(yTaps, dstHeight);
	const int sx = std::min(commonWeightShift(xTaps, dstWidth), 27 - sy);
	const int shift = 28 - sx - sy;
	if (shift > 22 || !isDoubling(xTaps, srcWidth, dstWidth)) {
		resampleRgb8_opt(src, srcStride, srcWidth, srcHeight, dst, dstStride, dstWidth,
				 dstHeight, xTaps, yTaps, rowTmp);
		return;
	}
	const int32_t bias = (int32_t(1) << (shift - 1)) - 1; // exact halves round down
	const int32_t q = (kOne / 4) >> sx;
	const int32x4_t biasV = vdupq_n_s32(bias), right = vdupq_n_s32(-shift);
	auto put = [&](uint8_t *o, int32_t v) {
		v >>= shift;
		*o = static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v));
	};
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		columnPass(src + ty.first * srcStride, srcStride, ty, sy, 3 * srcWidth, rowTmp);
		uint8_t *out = dst + y * dstStride;
		// The outer output pixels copy the outer input ones.
		for (int c = 0; c < 3; c++) {
			put(out + c, 4 * q * rowTmp[c] + bias);
			put(out + 3 * (dstWidth - 1) + c, 4 * q * rowTmp[3 * (srcWidth - 1) + c] + bias);
		}
		// Input pixels i - 1 and i give outputs 2i - 1 and 2i.
		int i = 1;
		for (; i + 8 <= srcWidth; i += 8) {
			const int32_t *a = rowTmp + 3 * (i - 1), *b = a + 3;
			const int32x4x3_t a0 = vld3q_s32(a), a1 = vld3q_s32(a + 12);
			const int32x4x3_t b0 = vld3q_s32(b), b1 = vld3q_s32(b + 12);
			uint8x16x3_t pixels;
			// 3 * q * near + q * far, for the four pixels of each half.
			auto mix = [&](int32x4_t near, int32x4_t far) {
				return vmlaq_n_s32(vmulq_n_s32(far, q), near, 3 * q);
			};
			for (int c = 0; c < 3; c++) {
				const uint8x8_t odd = toByte(mix(a0.val[c], b0.val[c]), mix(a1.val[c], b1.val[c]),
							     biasV, right);
				const uint8x8_t even = toByte(mix(b0.val[c], a0.val[c]), mix(b1.val[c], a1.val[c]),
							      biasV, right);
				const uint8x8x2_t zipped = vzip_u8(odd, even);
				pixels.val[c] = vcombine_u8(zipped.val[0], zipped.val[1]);
			}
			vst3q_u8(out + 3 * (2 * i - 1), pixels);
		}
		for (; i < srcWidth; i++) {
			const int32_t *a = rowTmp + 3 * (i - 1), *b = a + 3;
			uint8_t *odd = out + 3 * (2 * i - 1), *even = out + 3 * (2 * i);
			for (int c = 0; c < 3; c++) {
				put(odd + c, 3 * q * a[c] + q * b[c] + bias);
				put(even + c, q * a[c] + 3 * q * b[c] + bias);
			}
		}
	}
}

} // namespace kernels
} // namespace calped
