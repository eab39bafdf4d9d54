// SPDX-License-Identifier: BSD-2-Clause
// Depth-2 trees over four windows at a time with NEON (the scheme is in trees_batch.h).
// NEON has no gather: the two feature reads of a tree are four scalar loads each, the
// comparisons, leaf choice and cascade test are vector operations. Bit-identical to
// ref/trees_ref.cpp's scanDepth2_ref and scanDepth2List_ref.
#include <cstdint>

#include "arm/neon_util.h"
#include "kernels.h"
#include "trees_batch.h"

namespace calped {
namespace kernels {

namespace {

// With this many running lanes or fewer a batch is finished by the scalar loop.
constexpr int kScalarBelow = 1;

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
			const uint32_t o = tr.off[0];
			const int32_t f0v[4] = { w0[o], w1[o], w2[o], w3[o] };
			const uint32x4_t right = vcgeq_s32(vld1q_s32(f0v), vdupq_n_s32(tr.thr[0]));
			// Each lane's second node: its offset chosen per lane from the first test.
			uint32_t r[4];
			vst1q_u32(r, right);
			const uint32_t o1 = tr.off[1], o2 = tr.off[2];
			const int32_t f1v[4] = { w0[r[0] ? o2 : o1], w1[r[1] ? o2 : o1],
						 w2[r[2] ? o2 : o1], w3[r[3] ? o2 : o1] };
			const int32x4_t thr1 =
				vbslq_s32(right, vdupq_n_s32(tr.thr[2]), vdupq_n_s32(tr.thr[1]));
			const uint32x4_t second = vcgeq_s32(vld1q_s32(f1v), thr1);
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

uint64_t scanDepth2_neon(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
			 const Depth2Tree *trees, int nTrees, int32_t cascThr, WindowHit *hits,
			 uint64_t capacity)
{
	if (rows <= 0 || cols <= 0)
		return 0;
	const GridWindows win = { rows, cols, step, rowStride, 0, 0 };
	return scanDepth2Batched<4>(chns, win, trees, nTrees, cascThr, kScalarBelow, hits, capacity,
				    NeonWalk());
}

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
