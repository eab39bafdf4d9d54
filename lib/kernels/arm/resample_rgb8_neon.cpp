// SPDX-License-Identifier: BSD-2-Clause
// RGB8 resampling with NEON for the toolbox's exact 2x enlargement (the input "resize 2"):
// the column pass eight bytes at a time, then each pair of neighbouring input pixels
// a, b gives the outputs (3a + b) / 4 and (a + 3b) / 4, eight pairs of pixels at a time
// with de-interleaving loads and an interleaving store. Weights are divided by their
// common power of two as in the portable body (opt/resample_rgb8_body.h), so the sums
// fit 32 bits. Other ratios take the split sums of opt/resample_rgb8_split.h, four
// output samples (a quad) per vector: the quad's 16 source bytes of a row are loaded once,
// its taps' samples picked by a table lookup, multiplied by their weights into row sums,
// and the rows' split sums combined. Bit-identical to ref/resample_ref.cpp; ratios that
// cannot be planned (shrinking by more than about 4.5x, rows under 16 samples) use the
// portable kernel.
#include <arm_neon.h>

#include "arm/neon_util.h"
#include "opt/resample_rgb8_body.h"
#include "opt/resample_rgb8_split.h"

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


// ---- any ratio: split sums over quads --------------------------------------------------
// Output samples per group: four quads and one 16-byte store on aarch64, two quads and an
// 8-byte store on armv7 (whose sixteen registers spill with four).
#if defined(__aarch64__)
constexpr int kGroupQuads = 4;
#else
constexpr int kGroupQuads = 2;
#endif
constexpr int kGroup = 4 * kGroupQuads;
constexpr int kChunkGroups = 512 / kGroup; // groups planned at a time (about 13 KB of stack)

// A quad with its pairs laid out for widening multiplies: bytes of the samples' first
// taps in the low half of each lookup, second taps in the high half.
struct NeonQuad {
	int32_t base;
	uint8_t index[kSplitMaxSteps][16];   // into a window of 16 or 32 bytes
	uint16_t weight[kSplitMaxSteps][8]; // per step: w first x 4, w second x 4
};

struct NeonGroup {
	int32_t start; // first output sample
	NeonQuad q[kGroupQuads];
};

bool planNeonGroup(const ResampleTap *xTaps, int start, int srcW3, int window, NeonGroup &g)
{
	g.start = start;
	for (int k = 0; k < kGroupQuads; k++) {
		QuadPlan p;
		if (!planQuad(xTaps, start + 4 * k, srcW3, window, p))
			return false;
		NeonQuad &q = g.q[k];
		q.base = p.base;
		for (int step = 0; step < kSplitMaxSteps; step++)
			for (int s = 0; s < 4; s++)
				for (int half = 0; half < 2; half++) {
					q.index[step][8 * half + 2 * s] = p.index[step][4 * s + 2 * half];
					q.index[step][8 * half + 2 * s + 1] = kZeroByte;
					q.weight[step][4 * half + s] = uint16_t(p.weight[step][2 * s + half]);
				}
	}
	return true;
}

inline int groupStart(int g, int dstW3)
{
	return g * kGroup + kGroup <= dstW3 ? g * kGroup : dstW3 - kGroup;
}

// Sixteen bytes picked from the 16 (or, Wide, 32) at `window`; other indices give 0.
template <bool Wide>
CALPED_NEON_INLINE uint16x8_t lookupPairs(const uint8_t *window, const uint8_t *index)
{
	const uint8x16_t i = vld1q_u8(index);
	if (Wide) {
		const uint8x16x2_t table = { { vld1q_u8(window), vld1q_u8(window + 16) } };
		return vreinterpretq_u16_u8(lookupBytes32(table, i));
	}
#if defined(__aarch64__)
	return vreinterpretq_u16_u8(vqtbl1q_u8(vld1q_u8(window), i));
#else
	const uint8x8x2_t t = { { vld1_u8(window), vld1_u8(window + 8) } };
	return vreinterpretq_u16_u8(vcombine_u8(vtbl2_u8(t, vget_low_u8(i)), vtbl2_u8(t, vget_high_u8(i))));
#endif
}

// Row sums H = sum_x wx * p of one quad of one source row.
template <int Steps, bool Wide>
CALPED_NEON_INLINE uint32x4_t rowSums(const uint8_t *row, const NeonQuad &q)
{
	uint32x4_t h = vdupq_n_u32(0);
	for (int step = 0; step < Steps; step++) {
		const uint16x8_t p = lookupPairs<Wide>(row + q.base, q.index[step]);
		const uint16x8_t w = vld1q_u16(q.weight[step]);
		h = step == 0 ? vmull_u16(vget_low_u16(p), vget_low_u16(w))
			      : vmlal_u16(h, vget_low_u16(p), vget_low_u16(w));
		h = vmlal_u16(h, vget_high_u16(p), vget_high_u16(w));
	}
	return h;
}

// The split of row sums H < 2^22: H >> 14 and H & 0x3FFF as 16-bit lanes.
CALPED_NEON_INLINE uint16x4_t highPart(uint32x4_t h)
{
	return vshrn_n_u32(h, 14);
}
CALPED_NEON_INLINE uint16x4_t lowPart(uint32x4_t h)
{
	return vand_u16(vmovn_u32(h), vdup_n_u16(0x3FFF));
}

// (A + ((B + 2^27 - 1) >> 14)) >> 14 as 16-bit lanes: exact halves round down.
CALPED_NEON_INLINE uint16x4_t roundSplit(uint32x4_t a, uint32x4_t b)
{
	return vshrn_n_u32(vsraq_n_u32(a, vaddq_u32(b, vdupq_n_u32((1u << 27) - 1)), 14), 14);
}

template <int Steps, bool Wide>
CALPED_NEON_INLINE uint16x4_t quadOut(const uint8_t *r0, ptrdiff_t srcStride, const ResampleTap &ty,
				      const NeonQuad &q)
{
	uint32x4_t a = vdupq_n_u32(0), b = a;
	for (int j = 0; j < ty.count; j++) {
		const uint32x4_t h = rowSums<Steps, Wide>(r0 + j * srcStride, q);
		const uint16_t w = uint16_t(ty.weight[j]);
		a = vmlal_n_u16(a, highPart(h), w);
		b = vmlal_n_u16(b, lowPart(h), w);
	}
	return roundSplit(a, b);
}

// At most two source rows (every enlarging row): the common case without the loop.
template <int Steps, bool Wide>
CALPED_NEON_INLINE uint16x4_t quadOutTwo(const uint8_t *r0, const uint8_t *r1, uint32x4_t w0,
					 uint32x4_t w1, const NeonQuad &q)
{
	const uint32x4_t h0 = rowSums<Steps, Wide>(r0, q), h1 = rowSums<Steps, Wide>(r1, q);
	const uint32x4_t low = vdupq_n_u32(0x3FFF);
	const uint32x4_t a = vmlaq_u32(vmulq_u32(vshrq_n_u32(h0, 14), w0), vshrq_n_u32(h1, 14), w1);
	const uint32x4_t b = vmlaq_u32(vmulq_u32(vandq_u32(h0, low), w0), vandq_u32(h1, low), w1);
	return roundSplit(a, b);
}

// Stores the quads quad(0), quad(1)... of a group as bytes.
template <typename QuadFn>
CALPED_NEON_INLINE void storeGroup(uint8_t *out, QuadFn quad)
{
	const uint8x8_t lo = vqmovn_u16(vcombine_u16(quad(0), quad(1)));
	if constexpr (kGroupQuads == 4)
		vst1q_u8(out, vcombine_u8(lo, vqmovn_u16(vcombine_u16(quad(2), quad(3)))));
	else
		vst1_u8(out, lo);
}

template <int Steps, bool Wide>
void runChunk(const uint8_t *src, ptrdiff_t srcStride, uint8_t *dst, ptrdiff_t dstStride,
	      int dstHeight, const ResampleTap *yTaps, const NeonGroup *groups, int nGroups)
{
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		const uint8_t *r0 = src + ty.first * srcStride;
		uint8_t *out = dst + y * dstStride;
		if (ty.count <= 2) {
			const uint8_t *r1 = ty.count == 2 ? r0 + srcStride : r0;
			const uint32x4_t w0 = vdupq_n_u32(uint32_t(ty.weight[0]));
			const uint32x4_t w1 = vdupq_n_u32(uint32_t(ty.count == 2 ? ty.weight[1] : 0));
			for (int g = 0; g < nGroups; g++) {
				const NeonGroup &p = groups[g];
				storeGroup(out + p.start, [&](int k) { return quadOutTwo<Steps, Wide>(r0, r1, w0, w1, p.q[k]); });
			}
			continue;
		}
		for (int g = 0; g < nGroups; g++) {
			const NeonGroup &p = groups[g];
			storeGroup(out + p.start, [&](int k) { return quadOut<Steps, Wide>(r0, srcStride, ty, p.q[k]); });
		}
	}
}

using RunChunkFn = void (*)(const uint8_t *src, ptrdiff_t srcStride, uint8_t *dst, ptrdiff_t dstStride,
			    int dstHeight, const ResampleTap *yTaps, const NeonGroup *groups, int nGroups);

RunChunkFn chunkRunner(int steps, bool wide)
{
	static const RunChunkFn narrow[] = { runChunk<1, false>, runChunk<2, false> };
	static const RunChunkFn wideWindow[] = { runChunk<1, true>, runChunk<2, true>, runChunk<3, true> };
	return wide ? wideWindow[steps - 1] : narrow[steps - 1];
}

// The window every group of a row plans in: 16 bytes, else 32, else 0 (none).
int planWindow(const ResampleTap *xTaps, int dstWidth, int srcW3, NeonGroup &scratch)
{
	const int dstW3 = 3 * dstWidth, nGroups = (dstW3 + kGroup - 1) / kGroup;
	for (int window : { kSplitNarrow, kSplitWide }) {
		bool planned = splitSumsFit(xTaps, dstWidth, splitMaxXTaps(window));
		for (int g = 0; g < nGroups && planned; g++)
			planned = planNeonGroup(xTaps, groupStart(g, dstW3), srcW3, window, scratch);
		if (planned)
			return window;
	}
	return 0;
}

// Resamples with the split sums; false, with nothing written, when the taps cannot be
// planned.
bool resampleAnyRatio(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, uint8_t *dst,
		      ptrdiff_t dstStride, int dstWidth, int dstHeight, const ResampleTap *xTaps,
		      const ResampleTap *yTaps)
{
	const int srcW3 = 3 * srcWidth, dstW3 = 3 * dstWidth;
	NeonGroup chunk[kChunkGroups];
	const int window = dstW3 >= kGroup && splitSumsFit(yTaps, dstHeight, kMaxTaps)
				   ? planWindow(xTaps, dstWidth, srcW3, chunk[0])
				   : 0;
	if (window == 0)
		return false;
	const RunChunkFn run = chunkRunner(splitSteps(xTaps, dstWidth), window == kSplitWide);
	const int nGroups = (dstW3 + kGroup - 1) / kGroup;
	for (int g0 = 0; g0 < nGroups; g0 += kChunkGroups) {
		const int n = nGroups - g0 < kChunkGroups ? nGroups - g0 : kChunkGroups;
		for (int g = 0; g < n; g++)
			planNeonGroup(xTaps, groupStart(g0 + g, dstW3), srcW3, window, chunk[g]);
		run(src, srcStride, dst, dstStride, dstHeight, yTaps, chunk, n);
	}
	return true;
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
		if (resampleAnyRatio(src, srcStride, srcWidth, dst, dstStride, dstWidth, dstHeight, xTaps,
				     yTaps))
			return;
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
