// SPDX-License-Identifier: BSD-2-Clause
// Soft-cascade evaluation of boosted trees over sliding windows, the reference
// (the toolbox's acfDetect). Features are uint16 channel values compared with
// integer thresholds; scores accumulate in Q16.
#include "kernels.h"

namespace calped {
namespace kernels {

namespace {

inline int32_t scoreDepth2(const uint16_t *w, const Depth2Tree *trees, int nTrees, int32_t cascThr)
{
	int32_t h = 0;
	for (int t = 0; t < nTrees; t++) {
		const Depth2Tree &tr = trees[t];
		const int right = w[tr.off[0]] >= tr.thr[0];
		const int node = 1 + right;
		const int leaf = 2 * right + (w[tr.off[node]] >= tr.thr[node]);
		h += tr.leaf[leaf];
		if (h <= cascThr)
			break;
	}
	return h;
}

inline int32_t scoreTrees(const uint16_t *w, const TreeNode *nodes, int nTrees, int nodesPerTree,
			  int32_t cascThr)
{
	int32_t h = 0;
	for (int t = 0; t < nTrees; t++) {
		const TreeNode *tree = nodes + size_t(t) * nodesPerTree;
		uint32_t k = 0;
		while (tree[k].child)
			k = tree[k].child + (w[tree[k].off] >= tree[k].thr ? 1 : 0);
		h += tree[k].leaf;
		if (h <= cascThr)
			break;
	}
	return h;
}

} // namespace

uint64_t scanDepth2_ref(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
			const Depth2Tree *trees, int nTrees, int32_t cascThr, WindowHit *hits,
			uint64_t capacity)
{
	uint64_t passed = 0;
	for (int c = 0; c < cols; c++)
		for (int r = 0; r < rows; r++) {
			const uint16_t *w = chns + ptrdiff_t(r) * step * rowStride + ptrdiff_t(c) * step;
			keepHit(scoreDepth2(w, trees, nTrees, cascThr), cascThr, r, c, hits, capacity, passed);
		}
	return passed;
}

uint64_t scanTrees_ref(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
		       const TreeNode *nodes, int nTrees, int nodesPerTree, int32_t cascThr,
		       WindowHit *hits, uint64_t capacity)
{
	uint64_t passed = 0;
	for (int c = 0; c < cols; c++)
		for (int r = 0; r < rows; r++) {
			const uint16_t *w = chns + ptrdiff_t(r) * step * rowStride + ptrdiff_t(c) * step;
			keepHit(scoreTrees(w, nodes, nTrees, nodesPerTree, cascThr), cascThr, r, c, hits,
			     capacity, passed);
		}
	return passed;
}

uint64_t scanDepth2List_ref(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			    size_t count, int step, const Depth2Tree *trees, int nTrees,
			    int32_t cascThr, WindowHit *hits, uint64_t capacity)
{
	uint64_t passed = 0;
	for (size_t i = 0; i < count; i++) {
		const int r = int(windows[i] >> 16), c = int(windows[i] & 0xFFFF);
		const uint16_t *w = chns + ptrdiff_t(r) * step * rowStride + ptrdiff_t(c) * step;
		keepHit(scoreDepth2(w, trees, nTrees, cascThr), cascThr, r, c, hits, capacity, passed);
	}
	return passed;
}

uint64_t scanTreesList_ref(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			   size_t count, int step, const TreeNode *nodes, int nTrees,
			   int nodesPerTree, int32_t cascThr, WindowHit *hits, uint64_t capacity)
{
	uint64_t passed = 0;
	for (size_t i = 0; i < count; i++) {
		const int r = int(windows[i] >> 16), c = int(windows[i] & 0xFFFF);
		const uint16_t *w = chns + ptrdiff_t(r) * step * rowStride + ptrdiff_t(c) * step;
		keepHit(scoreTrees(w, nodes, nTrees, nodesPerTree, cascThr), cascThr, r, c, hits,
		     capacity, passed);
	}
	return passed;
}

} // namespace kernels
} // namespace calped
