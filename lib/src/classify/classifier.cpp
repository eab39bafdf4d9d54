// SPDX-License-Identifier: BSD-2-Clause
#include "classify/classifier.h"

#include <algorithm>
#include <cmath>

namespace calped {

namespace {

// A complete depth-2 tree in the toolbox's layout: root -> 1, 2; 1 -> 3, 4; 2 -> 5, 6.
bool isCompleteDepth2(const Model &m, int t)
{
	if (m.nodesPerTree < 7)
		return false;
	const uint32_t *child = m.child.data() + size_t(t) * m.nodesPerTree;
	return child[0] == 1 && child[1] == 3 && child[2] == 5 && child[3] == 0 &&
	       child[4] == 0 && child[5] == 0 && child[6] == 0;
}

} // namespace

void Classifier::init(const Model &model, ptrdiff_t rowStride, ptrdiff_t planeStride,
		      const kernels::KernelTable &k)
{
	k_ = &k;
	params_ = model.params;
	nTrees_ = model.nTrees;
	nodesPerTree_ = model.nodesPerTree;
	shrink_ = model.classifierShrink();
	setCascadeThreshold(model.params.cascThr);

	// Feature id -> offset: ids run down the window's rows, then columns, then channels.
	const int rows = model.params.modelDsPadH / shrink_;
	const int cols = model.params.modelDsPadW / shrink_;
	// LDCF's trees read the filtered channels (biased Q12): the same splits moved there.
	const bool filtered = model.params.nFilters > 0;
	auto threshold = [&](int32_t q14) { return filtered ? LdcfFilter::thresholdFor(q14) : q14; };
	auto offset = [&](uint32_t fid) {
		const uint32_t r = fid % rows, c = (fid / rows) % cols, z = fid / (rows * cols);
		return static_cast<uint32_t>(z * planeStride + r * rowStride + c);
	};

	depth2_ = true;
	for (int t = 0; t < nTrees_ && depth2_; t++)
		depth2_ = isCompleteDepth2(model, t);

	if (depth2_) {
		depth2Trees_.resize(nTrees_);
		for (int t = 0; t < nTrees_; t++) {
			const size_t b = size_t(t) * nodesPerTree_;
			kernels::Depth2Tree &d = depth2Trees_[t];
			for (int k = 0; k < 3; k++) {
				d.off[k] = offset(model.fids[b + k]);
				d.thr[k] = threshold(model.thrs[b + k]);
			}
			for (int k = 0; k < 4; k++)
				d.leaf[k] = model.hs[b + 3 + k];
		}
	} else {
		nodes_.resize(size_t(nTrees_) * nodesPerTree_);
		for (size_t i = 0; i < nodes_.size(); i++) {
			kernels::TreeNode &n = nodes_[i];
			n.child = model.child[i];
			n.off = n.child ? offset(model.fids[i]) : 0;
			n.thr = threshold(model.thrs[i]);
			n.leaf = model.hs[i];
		}
	}
}

void Classifier::setCascadeThreshold(float thr)
{
	// A Q16 score h satisfies h / 2^16 <= thr exactly when h <= floor(thr * 2^16).
	cascThr_ = static_cast<int32_t>(std::floor(double(thr) * (1 << kScoreFracBits)));
}

void Classifier::windowGrid(int paddedHeight, int paddedWidth, int &rows, int &cols) const
{
	const int shrink = shrink_, stride = params_.stride;
	// The toolbox's window counts: ceil((size * shrink - model + 1) / stride).
	rows = std::max(0, (paddedHeight * shrink - params_.modelDsPadH + stride) / stride);
	cols = std::max(0, (paddedWidth * shrink - params_.modelDsPadW + stride) / stride);
}

int32_t Classifier::scoreOnDemand(LdcfFilter &level, ptrdiff_t base) const
{
	int32_t h = 0;
	if (depth2_) {
		for (int t = 0; t < nTrees_; t++) {
			const kernels::Depth2Tree &tr = depth2Trees_[size_t(t)];
			const int right = level.at(base + tr.off[0]) >= tr.thr[0];
			const int node = 1 + right;
			h += tr.leaf[2 * right + (level.at(base + tr.off[node]) >= tr.thr[node])];
			if (h <= cascThr_)
				break;
		}
		return h;
	}
	for (int t = 0; t < nTrees_; t++) {
		const kernels::TreeNode *tree = nodes_.data() + size_t(t) * nodesPerTree_;
		uint32_t k = 0;
		while (tree[k].child)
			k = tree[k].child + (level.at(base + tree[k].off) >= tree[k].thr ? 1 : 0);
		h += tree[k].leaf;
		if (h <= cascThr_)
			break;
	}
	return h;
}

uint64_t Classifier::scanList(const LevelChannels &level, const uint32_t *windows, size_t count,
			      kernels::WindowHit *hits, uint64_t capacity) const
{
	const int step = params_.stride / shrink_;
	if (level.onDemand) {
		uint64_t passed = 0;
		for (size_t i = 0; i < count; i++) {
			const int r = int(windows[i] >> 16), c = int(windows[i] & 0xFFFF);
			const ptrdiff_t base = ptrdiff_t(r) * step * level.rowStride + ptrdiff_t(c) * step;
			kernels::keepHit(scoreOnDemand(*level.onDemand, base), cascThr_, r, c, hits, capacity, passed);
		}
		return passed;
	}
	if (depth2_)
		return k_->scanDepth2List(level.data, level.rowStride, windows, count, step,
					  depth2Trees_.data(), nTrees_, cascThr_, hits, capacity);
	return k_->scanTreesList(level.data, level.rowStride, windows, count, step, nodes_.data(),
				 nTrees_, nodesPerTree_, cascThr_, hits, capacity);
}

uint64_t Classifier::scan(const LevelChannels &level, kernels::WindowHit *hits,
			  uint64_t capacity, uint64_t *windows) const
{
	const int shrink = shrink_, stride = params_.stride;
	int rows, cols;
	windowGrid(level.paddedHeight, level.paddedWidth, rows, cols);
	if (rows <= 0 || cols <= 0)
		return 0;
	*windows += uint64_t(rows) * cols;
	const int step = stride / shrink;
	if (level.onDemand) {
		uint64_t passed = 0;
		for (int c = 0; c < cols; c++)
			for (int r = 0; r < rows; r++) {
				const ptrdiff_t base = ptrdiff_t(r) * step * level.rowStride + ptrdiff_t(c) * step;
				kernels::keepHit(scoreOnDemand(*level.onDemand, base), cascThr_, r, c, hits, capacity, passed);
			}
		return passed;
	}
	if (depth2_)
		return k_->scanDepth2(level.data, level.rowStride, rows, cols, step,
					       depth2Trees_.data(), nTrees_, cascThr_, hits, capacity);
	return k_->scanTrees(level.data, level.rowStride, rows, cols, step, nodes_.data(),
				      nTrees_, nodesPerTree_, cascThr_, hits, capacity);
}

} // namespace calped
