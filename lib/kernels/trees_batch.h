// SPDX-License-Identifier: BSD-2-Clause
// Depth-2 trees evaluated several windows at a time (the SIMD tables' scanDepth2 and
// scanDepth2List), shared by x86/trees_avx2.cpp and arm/trees_neon.cpp.
//
// A batch of Lanes consecutive windows walks the trees in lock step: every lane tests the
// same tree, so the tree's offsets, thresholds and leaves are broadcast and only the two
// feature reads differ per lane. A lane whose score falls to the cascade threshold stops
// adding (its score is frozen, exactly where the scalar loop would break). Most windows
// stop within a few trees, a few go on much longer: once no more than `scalarBelow` lanes
// are left, they finish one by one in the scalar loop from the tree the batch reached.
// Hits are written in window order, so output is identical to ref/trees_ref.cpp's.
//
// Everything here has internal linkage: each ISA's file compiles its own copy with its
// own flags.
#pragma once

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

// Per-lane outcome of the lock-step walk over one batch.
struct BatchState {
	int32_t h[16];       // score so far (frozen where the lane stopped)
	bool running[16];    // still above the threshold when the walk ended
	int tree = 0;        // first tree the walk did not evaluate
};

// The scalar loop of the reference, from tree t on with score h.
inline int32_t finishDepth2(const uint16_t *w, const Depth2Tree *trees, int t, int nTrees,
			    int32_t h, int32_t cascThr)
{
	for (; t < nTrees; t++) {
		const Depth2Tree &tr = trees[t];
		const int right = w[tr.off[0]] >= tr.thr[0];
		const int node = 1 + right;
		h += tr.leaf[2 * right + (w[tr.off[node]] >= tr.thr[node])];
		if (h <= cascThr)
			break;
	}
	return h;
}

// Windows in the reference's order, read one after another: a grid (columns outer, rows
// inner) or a list of row << 16 | column.
struct GridWindows {
	int rows, cols, step;
	ptrdiff_t rowStride;
	int r = 0, c = 0; // the next window
	uint64_t count() const { return uint64_t(rows) * cols; }
	void next(int &row, int &col)
	{
		row = r, col = c;
		if (++r == rows)
			r = 0, c++;
	}
};
struct ListWindows {
	const uint32_t *windows;
	size_t n;
	int step;
	ptrdiff_t rowStride;
	size_t i = 0; // the next window
	uint64_t count() const { return n; }
	void next(int &row, int &col)
	{
		row = int(windows[i] >> 16);
		col = int(windows[i] & 0xFFFF);
		i++;
	}
};

// Walk: void(const uint16_t *chns, const int32_t *base, int n, const Depth2Tree *trees,
// int nTrees, int32_t cascThr, int scalarBelow, BatchState &s), n <= Lanes; base holds
// Lanes element offsets below 2^30 (lanes n.. repeat a valid one), and base + a tree's
// offset must fit 32 bits unsigned (a level buffer under 8 GB). Windows further out take
// the scalar loop.
template <int Lanes, class Walk, class Windows>
uint64_t scanDepth2Batched(const uint16_t *chns, Windows win, const Depth2Tree *trees,
			   int nTrees, int32_t cascThr, int scalarBelow, WindowHit *hits,
			   uint64_t capacity, Walk walk)
{
	static_assert(Lanes <= 16, "BatchState holds 16 lanes");
	const uint64_t count = win.count();
	uint64_t passed = 0;
	int32_t base[Lanes];
	int rs[Lanes], cs[Lanes];
	BatchState s;
	for (uint64_t i = 0; i < count; i += Lanes) {
		const int n = int(count - i < uint64_t(Lanes) ? count - i : uint64_t(Lanes));
		ptrdiff_t at[Lanes];
		bool small = true; // offsets the lanes' 32 bits hold (any real level's do)
		for (int l = 0; l < Lanes; l++) {
			if (l < n)
				win.next(rs[l], cs[l]);
			else
				rs[l] = rs[0], cs[l] = cs[0];
			at[l] = ptrdiff_t(rs[l]) * win.step * win.rowStride + ptrdiff_t(cs[l]) * win.step;
			small = small && at[l] <= 0x3FFFFFFF;
			base[l] = int32_t(at[l]);
		}
		if (small) {
			walk(chns, base, n, trees, nTrees, cascThr, scalarBelow, s);
		} else {
			s.tree = 0;
			for (int l = 0; l < n; l++)
				s.h[l] = 0, s.running[l] = true;
		}
		for (int l = 0; l < n; l++) {
			int32_t h = s.h[l];
			if (s.running[l])
				h = finishDepth2(chns + at[l], trees, s.tree, nTrees, h, cascThr);
			keepHit(h, cascThr, rs[l], cs[l], hits, capacity, passed);
		}
	}
	return passed;
}

} // namespace
} // namespace kernels
} // namespace calped
