// SPDX-License-Identifier: BSD-2-Clause
// Plane resampling with NEON. Row pass: exact halving (the computed octaves) is the
// rounding halving add of even and odd samples; other ratios work on blocks of eight
// outputs, planned once for all the planes of a level. When their taps all fall within
// 16 consecutive source samples (any ratio below about 1.7) the 16 samples are loaded once
// and each tap's samples picked by a byte table lookup (as many lookups as the block's
// outputs have taps at most); shrinking by up to 8, each output multiplies its own 8 samples by its weights
// padded with zeros and sums across lanes. Column pass: whole rows of widening
// multiply-accumulates. Bit-identical to ref/resample_ref.cpp: weights are non-negative
// and sum to at most gain * 2^14, so 32-bit sums suffice, and (acc + 2^13) >> 14
// saturated is VQRSHRN.
#include <arm_neon.h>

#include "opt/resample_body.h"
#include "arm/neon_util.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kChunk = 64; // blocks planned at a time (bounded stack use)

// How a block of eight outputs is computed for every row.
enum class BlockKind {
	Scalar, // one output at a time
	Window, // all taps within 16 consecutive samples (at most 3 taps per output)
	Wide,   // up to 8 taps per output, each output from its own 8 samples
};

struct WindowPlan {
	int32_t base;          // first of the 16 source samples
	int32_t taps;          // the most taps of the block's outputs (1 to 3)
	uint8_t bytes[3][16];  // per tap: byte indices of each output's sample within the 16
	uint16_t weight[3][8]; // per tap: each output's weight (0 for a missing tap)
};

struct WidePlan {
	int32_t first[8];      // per output: its first source sample
	uint16_t weight[8][8]; // per output: its weights, 0 past its tap count
};

struct BlockPlan {
	BlockKind kind;
	int x0; // first output of the block
	union {
		WindowPlan window;
		WidePlan wide;
	};
};

inline bool weightFits16(int32_t w) { return w >= 0 && w <= 65535; }

bool planWindow(const ResampleTap *taps, int x0, int srcWidth, WindowPlan &p)
{
	// The 16 samples start at the block's first tap, or earlier at the right edge so
	// that they stay inside the row.
	const int base = std::min(taps[x0].first, srcWidth - 16);
	if (base < 0)
		return false;
	p.taps = 1;
	for (int i = 0; i < 8; i++) {
		const ResampleTap &t = taps[x0 + i];
		if (t.count > 3 || t.first < base || t.first + t.count - base > 16)
			return false;
		p.taps = std::max(p.taps, t.count);
		for (int j = 0; j < 3; j++) {
			if (!weightFits16(t.weight[j < t.count ? j : 0]))
				return false;
			const int sample = (j < t.count ? t.first + j : t.first) - base;
			p.bytes[j][2 * i] = uint8_t(2 * sample);
			p.bytes[j][2 * i + 1] = uint8_t(2 * sample + 1);
			p.weight[j][i] = uint16_t(j < t.count ? t.weight[j] : 0);
		}
	}
	p.base = base;
	return true;
}

// Shrinking by 2 to 8 (the smaller computed octaves): each output's taps padded to 8.
bool planWide(const ResampleTap *taps, int x0, int srcWidth, WidePlan &p)
{
	for (int i = 0; i < 8; i++) {
		const ResampleTap &t = taps[x0 + i];
		if (t.count > 8 || t.first + 8 > srcWidth)
			return false;
		p.first[i] = t.first;
		for (int j = 0; j < 8; j++) {
			if (j < t.count && !weightFits16(t.weight[j]))
				return false;
			p.weight[i][j] = uint16_t(j < t.count ? t.weight[j] : 0);
		}
	}
	return true;
}

BlockKind planBlock(const ResampleTap *taps, int x0, int srcWidth, BlockPlan &p)
{
	p.x0 = x0;
	if (planWindow(taps, x0, srcWidth, p.window))
		return BlockKind::Window;
	if (planWide(taps, x0, srcWidth, p.wide))
		return BlockKind::Wide;
	return BlockKind::Scalar;
}

inline uint16_t rowSample(const uint16_t *in, const ResampleTap &t)
{
	const uint16_t *p = in + t.first;
	uint32_t acc = 0;
	for (int j = 0; j < t.count; j++)
		acc += uint32_t(t.weight[j]) * p[j];
	return roundQ14(acc);
}

bool isHalving(const ResampleTap *taps, int dstWidth)
{
	for (int x = 0; x < dstWidth; x++) {
		const ResampleTap &t = taps[x];
		if (t.count != 2 || t.first != 2 * x || t.weight[0] != kOne / 2 || t.weight[1] != kOne / 2)
			return false;
	}
	return true;
}

// Exactly half the width: (a + b + 1) >> 1 is the rounding halving add.
void halveRows(const uint16_t *src, ptrdiff_t srcStride, int srcHeight, int dstWidth,
	       uint16_t *tmp, ptrdiff_t tmpStride)
{
	for (int y = 0; y < srcHeight; y++) {
		const uint16_t *in = src + y * srcStride;
		uint16_t *out = tmp + y * tmpStride;
		int x = 0;
		for (; x + 8 <= dstWidth; x += 8) {
			const uint16x8x2_t s = vld2q_u16(in + 2 * x); // even and odd samples
			vst1q_u16(out + x, vrhaddq_u16(s.val[0], s.val[1]));
		}
		for (; x < dstWidth; x++)
			out[x] = static_cast<uint16_t>((uint32_t(in[2 * x]) + in[2 * x + 1] + 1) >> 1);
	}
}

// A planned block in registers, for all the rows of a strip.
struct BlockRegs {
	uint8x16_t bytes[3];
	uint16x8_t weight[3];
};

inline BlockRegs loadPlan(const WindowPlan &p)
{
	BlockRegs r;
	for (int j = 0; j < 3; j++) {
		r.bytes[j] = vld1q_u8(p.bytes[j]);
		r.weight[j] = vld1q_u16(p.weight[j]);
	}
	return r;
}

// Eight outputs of one row from the 16 samples at `in`, with the plan's first Taps taps
// (the others have weight 0 throughout the block).
template <int Taps>
inline uint16x8_t plannedBlock(const BlockRegs &p, const uint16_t *in)
{
	const uint8x16x2_t samples = { { vreinterpretq_u8_u16(vld1q_u16(in)),
					 vreinterpretq_u8_u16(vld1q_u16(in + 8)) } };
	uint32x4_t lo = vdupq_n_u32(0), hi = vdupq_n_u32(0);
	for (int j = 0; j < Taps; j++) {
		const uint16x8_t s = vreinterpretq_u16_u8(lookupBytes32(samples, p.bytes[j]));
		lo = vmlal_u16(lo, vget_low_u16(s), vget_low_u16(p.weight[j]));
		hi = vmlal_u16(hi, vget_high_u16(s), vget_high_u16(p.weight[j]));
	}
	return vcombine_u16(vqrshrn_n_u32(lo, kQ), vqrshrn_n_u32(hi, kQ));
}

// Eight outputs of one row from a wide plan: each output's 8 samples times its 8 weights,
// summed across lanes.
inline uint16x8_t wideBlock(const WidePlan &p, const uint16_t *in)
{
	uint32x4_t acc[8];
	for (int i = 0; i < 8; i++) {
		const uint16x8_t s = vld1q_u16(in + p.first[i]), w = vld1q_u16(p.weight[i]);
		acc[i] = vmlal_u16(vmull_u16(vget_low_u16(s), vget_low_u16(w)), vget_high_u16(s),
				   vget_high_u16(w));
	}
	const uint32x4_t lo = horizontalSums4(acc[0], acc[1], acc[2], acc[3]);
	const uint32x4_t hi = horizontalSums4(acc[4], acc[5], acc[6], acc[7]);
	return vcombine_u16(vqrshrn_n_u32(lo, kQ), vqrshrn_n_u32(hi, kQ));
}

// One chunk of up to kChunk blocks across: outputs [first, end), planned once for every
// plane of a level; blocks run from `first` (the last may start earlier and overlap the
// one before it, writing the same values there), outputs from `tail` on one at a time.
struct ChunkPlan {
	BlockPlan plans[kChunk + 1];
	int blocks, first, tail, end;
};

void planChunk(const ResampleTap *xTaps, int chunk, int srcWidth, int dstWidth, ChunkPlan &c)
{
	c.blocks = std::min(kChunk, (dstWidth - chunk) / 8);
	for (int b = 0; b < c.blocks; b++)
		c.plans[b].kind = planBlock(xTaps, chunk + 8 * b, srcWidth, c.plans[b]);
	c.end = std::min(dstWidth, chunk + 8 * kChunk);
	c.tail = chunk + 8 * c.blocks;
	if (c.tail < c.end && dstWidth >= 8) {
		c.plans[c.blocks].kind = planBlock(xTaps, dstWidth - 8, srcWidth, c.plans[c.blocks]);
		c.blocks++;
		c.tail = c.end;
	}
	c.first = c.blocks > 0 ? std::min(chunk, c.plans[c.blocks - 1].x0) : chunk;
}

template <int Taps>
void windowRows(const WindowPlan &w, const uint16_t *in, ptrdiff_t srcStride, int rows, uint16_t *out,
		ptrdiff_t tmpStride)
{
	const BlockRegs regs = loadPlan(w);
	for (int y = 0; y < rows; y++, in += srcStride, out += tmpStride)
		vst1q_u16(out, plannedBlock<Taps>(regs, in + w.base));
}

// The row pass of one chunk: strips of rows down, each block's plan in registers for a
// strip, and a strip's rows in the cache for all the chunk's blocks.
void rowPassChunk(const ChunkPlan &c, const uint16_t *src, ptrdiff_t srcStride, int srcHeight,
		  const ResampleTap *xTaps, uint16_t *tmp, ptrdiff_t tmpStride)
{
	constexpr int kStrip = 16;
	for (int y0 = 0; y0 < srcHeight; y0 += kStrip) {
		const int rows = std::min(srcHeight - y0, kStrip);
		for (int b = 0; b < c.blocks; b++) {
			const BlockPlan &p = c.plans[b];
			const int x0 = p.x0;
			const uint16_t *in = src + y0 * srcStride;
			uint16_t *out = tmp + y0 * tmpStride + x0;
			if (p.kind == BlockKind::Window) {
				if (p.window.taps == 1)
					windowRows<1>(p.window, in, srcStride, rows, out, tmpStride);
				else if (p.window.taps == 2)
					windowRows<2>(p.window, in, srcStride, rows, out, tmpStride);
				else
					windowRows<3>(p.window, in, srcStride, rows, out, tmpStride);
			} else if (p.kind == BlockKind::Wide) {
				for (int y = 0; y < rows; y++, in += srcStride, out += tmpStride)
					vst1q_u16(out, wideBlock(p.wide, in));
			} else {
				for (int y = 0; y < rows; y++, in += srcStride, out += tmpStride)
					for (int i = 0; i < 8; i++)
						out[i] = rowSample(in, xTaps[x0 + i]);
			}
		}
		for (int y = y0; y < y0 + rows; y++)
			for (int x = c.tail; x < c.end; x++)
				tmp[y * tmpStride + x] = rowSample(src + y * srcStride, xTaps[x]);
	}
}

// Column pass for one output row: rows r0 + j * tmpStride weighted by t's weights.
// Taps > 0 is the tap count (unrolled; weights below 2^16, widening multiply-accumulates
// of 16-bit lanes); 0 takes any count and weight.
template <int Taps>
void columnRow(const ResampleTap &t, const uint16_t *r0, ptrdiff_t tmpStride, int dstWidth,
	       uint16_t *out)
{
	const int n = Taps > 0 ? Taps : t.count;
	int x = 0;
	for (; x + 8 <= dstWidth; x += 8) {
		uint32x4_t lo = vdupq_n_u32(0), hi = vdupq_n_u32(0);
		for (int j = 0; j < n; j++) {
			const uint16x8_t s = vld1q_u16(r0 + j * tmpStride + x);
			if constexpr (Taps > 0) {
				const uint16_t w = uint16_t(t.weight[j]);
				lo = vmlal_n_u16(lo, vget_low_u16(s), w);
				hi = vmlal_n_u16(hi, vget_high_u16(s), w);
			} else {
				const uint32x4_t w = vdupq_n_u32(uint32_t(t.weight[j]));
				lo = vmlaq_u32(lo, vmovl_u16(vget_low_u16(s)), w);
				hi = vmlaq_u32(hi, vmovl_u16(vget_high_u16(s)), w);
			}
		}
		vst1q_u16(out + x, vcombine_u16(vqrshrn_n_u32(lo, kQ), vqrshrn_n_u32(hi, kQ)));
	}
	for (; x < dstWidth; x++) {
		uint32_t acc = 0;
		for (int j = 0; j < n; j++)
			acc += uint32_t(t.weight[j]) * r0[j * tmpStride + x];
		out[x] = roundQ14(acc);
	}
}

void columnPass(uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		const ResampleTap *yTaps, const uint16_t *tmp, ptrdiff_t tmpStride)
{
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &t = yTaps[y];
		const uint16_t *r0 = tmp + t.first * tmpStride;
		uint16_t *out = dst + y * dstStride;
		bool small = true; // every weight fits 16 bits
		for (int j = 0; j < t.count; j++)
			small = small && t.weight[j] >= 0 && t.weight[j] <= 65535;
		if (small && t.count == 1)
			columnRow<1>(t, r0, tmpStride, dstWidth, out);
		else if (small && t.count == 2)
			columnRow<2>(t, r0, tmpStride, dstWidth, out);
		else if (small && t.count == 3)
			columnRow<3>(t, r0, tmpStride, dstWidth, out);
		else
			columnRow<0>(t, r0, tmpStride, dstWidth, out);
	}
}

} // namespace

// Chunk by chunk of outputs across: the blocks are planned once for all the planes (a
// level's channels share their row taps), then each plane's rows and columns in that
// chunk are resampled (tmp holds one plane's chunk at a time).
void resamplePlanes_neon(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			 int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			 ptrdiff_t tmpStride)
{
	if (isHalving(xTaps, dstWidth)) {
		for (int i = 0; i < count; i++) {
			const PlaneJob &j = jobs[i];
			halveRows(j.src, j.srcStride, srcHeight, dstWidth, tmp, tmpStride);
			columnPass(j.dst, j.dstStride, dstWidth, dstHeight, j.yTaps, tmp, tmpStride);
		}
		return;
	}
	ChunkPlan c;
	for (int chunk = 0; chunk < dstWidth; chunk += 8 * kChunk) {
		planChunk(xTaps, chunk, srcWidth, dstWidth, c);
		for (int i = 0; i < count; i++) {
			const PlaneJob &j = jobs[i];
			rowPassChunk(c, j.src, j.srcStride, srcHeight, xTaps, tmp, tmpStride);
			columnPass(j.dst + c.first, j.dstStride, c.end - c.first, dstHeight, j.yTaps,
				   tmp + c.first, tmpStride);
		}
	}
}

void resamplePlane_neon(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
			ptrdiff_t tmpStride)
{
	const PlaneJob job = { src, srcStride, dst, dstStride, yTaps };
	resamplePlanes_neon(&job, 1, srcWidth, srcHeight, dstWidth, dstHeight, xTaps, tmp, tmpStride);
}

} // namespace kernels
} // namespace calped
