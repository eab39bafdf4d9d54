// SPDX-License-Identifier: BSD-2-Clause
// Depth-2 trees over four listed windows at a time with NEON (the scheme is in
// trees_batch.h). NEON has no gather: the two feature reads of a tree are four lane loads
// each, the comparisons, leaf choice and cascade test are vector operations. Bit-identical
// to ref/trees_ref.cpp's scanDepth2List_ref. Only the calibrated mode's window lists use
// it: its windows go 32 trees deep on average, where the lock step pays (qemu plugin,
// aarch64: 117.1 -> 114.8 M instructions per frame); the generic grid's windows stop after
// 5.2 trees and four lanes wait too long for the last (338.2 -> 342.1 M), so the grid
// keeps the scalar reference (docs/cross-compiling.md).
#include <cstdint>

#include "arm/neon_util.h"
#include "kernels.h"
#include "trees_batch.h"

namespace calped {
namespace kernels {

namespace {

// With this many running lanes or fewer a batch is finished by the scalar loop (1: 116.1,
// 2: 114.8, 3: 115.2 M instructions per calibrated frame).
constexpr int kScalarBelow = 2;

CALPED_NEON_INLINE int lanesSet(uint32x4_t mask)
{
	const uint32x4_t ones = vshrq_n_u32(mask, 31);
#ifdef __aarch64__
	return int(vaddvq_u32(ones));
#else
	uint32x2_t s = vadd_u32(vget_low_u32(ones), vget_high_u32(ones));
	s = vpadd_u32(s, s);
	return int(vget_lane_u32(s, 0));
#endif
}

struct NeonWalk {
	void operator()(const uint16_t *chns, const int32_t *base, int n, const Depth2Tree *trees,
			int nTrees, int32_t cascThr, int scalarBelow, BatchState &s) const
	{
		const uint16_t *w0 = chns + base[0], *w1 = chns + base[1], *w2 = chns + base[2],
			       *w3 = chns + base[3];
		const int32x4_t thr = vdupq_n_s32(cascThr);
		const int32_t lane[4] = { 0, 1, 2, 3 };
		uint32x4_t running = vcltq_s32(vld1q_s32(lane), vdupq_n_s32(n));
		int32x4_t h = vdupq_n_s32(0);
		int live = n, t = 0;
		for (; t < nTrees && live > scalarBelow; t++) {
			const Depth2Tree &tr = trees[t];
			// Lane loads straight into a vector (no round trip through memory).
			const uint32_t o = tr.off[0];
			uint16x4_t f0 = vld1_dup_u16(w0 + o);
			f0 = vld1_lane_u16(w1 + o, f0, 1);
			f0 = vld1_lane_u16(w2 + o, f0, 2);
			f0 = vld1_lane_u16(w3 + o, f0, 3);
			const uint32x4_t right =
				vcgeq_s32(vreinterpretq_s32_u32(vmovl_u16(f0)), vdupq_n_s32(tr.thr[0]));
			// Each lane's second node: offset off[1] + (off[2] - off[1]) where right.
			const uint32x4_t off = vbslq_u32(right, vdupq_n_u32(tr.off[2]), vdupq_n_u32(tr.off[1]));
			uint16x4_t f1 = vld1_dup_u16(w0 + vgetq_lane_u32(off, 0));
			f1 = vld1_lane_u16(w1 + vgetq_lane_u32(off, 1), f1, 1);
			f1 = vld1_lane_u16(w2 + vgetq_lane_u32(off, 2), f1, 2);
			f1 = vld1_lane_u16(w3 + vgetq_lane_u32(off, 3), f1, 3);
			const int32x4_t thr1 =
				vbslq_s32(right, vdupq_n_s32(tr.thr[2]), vdupq_n_s32(tr.thr[1]));
			const uint32x4_t second = vcgeq_s32(vreinterpretq_s32_u32(vmovl_u16(f1)), thr1);
			const int32x4_t left =
				vbslq_s32(second, vdupq_n_s32(tr.leaf[1]), vdupq_n_s32(tr.leaf[0]));
			const int32x4_t rightLeaf =
				vbslq_s32(second, vdupq_n_s32(tr.leaf[3]), vdupq_n_s32(tr.leaf[2]));
			const int32x4_t leaf = vbslq_s32(right, rightLeaf, left);
			h = vaddq_s32(h, vandq_s32(leaf, vreinterpretq_s32_u32(running)));
			running = vandq_u32(running, vcgtq_s32(h, thr));
			live = lanesSet(running);
		}
		uint32_t run[4];
		vst1q_s32(s.h, h);
		vst1q_u32(run, running);
		for (int l = 0; l < 4; l++)
			s.running[l] = run[l] != 0;
		s.tree = t;
	}
};

} // namespace

uint64_t scanDepth2List_neon(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			     size_t count, int step, const Depth2Tree *trees, int nTrees,
			     int32_t cascThr, WindowHit *hits, uint64_t capacity)
{
	const ListWindows win = { windows, count, step, rowStride, 0 };
	return scanDepth2Batched<4>(chns, win, trees, nTrees, cascThr, kScalarBelow, hits, capacity,
				    NeonWalk());
}

} // namespace kernels
} // namespace calped
