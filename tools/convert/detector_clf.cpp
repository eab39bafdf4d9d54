// SPDX-License-Identifier: BSD-2-Clause
#include "detector_clf.h"

#include <cmath>
#include <cstdint>

#include "model/fixed_convert.h"
#include "model/tree_walk.h"

namespace calped {
namespace convert {

namespace {

constexpr size_t kMaxNodes = 255;    // blob limit on nodesPerTree
constexpr size_t kMaxTrees = 1 << 16; // blob limit on nTrees

Status readArray(const MatNode &clf, const char *name, RawArray &out)
{
	MatNode node;
	Status s = field(clf, name, node);
	if (s.ok())
		s = numbers(node, out.values, &out.cls);
	if (!s.ok())
		return s;
	if (!matrixShape(node, out.rows, out.cols) || out.rows == 0 || out.cols == 0)
		return Status::error(ErrorCode::ModelInvalid, "%s is %s, expected nodes x trees",
				     node.path.c_str(), shapeString(node).c_str());
	out.name = name;
	return Status::success();
}

Status toIndex(const RawArray &a, size_t i, uint32_t &out)
{
	const double v = a.values[i];
	if (!(v >= 0 && v <= 4294967295.0 && v == std::floor(v)))
		return Status::error(ErrorCode::ModelInvalid,
				     "clf.%s(%zu, %zu) = %.17g is not an unsigned 32-bit integer",
				     a.name.c_str(), i % a.rows + 1, i / a.rows + 1, v);
	out = static_cast<uint32_t>(v);
	return Status::success();
}

Status toFinite(const RawArray &a, size_t i, double &out)
{
	out = a.values[i];
	if (!std::isfinite(out))
		return Status::error(ErrorCode::ModelInvalid, "clf.%s(%zu, %zu) = %g is not finite",
				     a.name.c_str(), i % a.rows + 1, i / a.rows + 1, out);
	return Status::success();
}

// The walk is calped's definition of depth; the toolbox's array must agree with it.
Status checkDepths(const RawArray &depthArray, size_t base, const std::vector<int32_t> &depth,
		   int32_t tree)
{
	for (size_t k = 0; k < depth.size(); k++) {
		if (depth[k] < 0)
			continue; // unused slots hold 0
		if (depthArray.values[base + k] != depth[k])
			return Status::error(ErrorCode::ModelInvalid,
					     "clf.depth(%zu, %d) = %g but the node is at depth %d",
					     k + 1, tree + 1, depthArray.values[base + k], depth[k]);
	}
	return Status::success();
}

} // namespace

Status readClf(const MatNode &clf, RawClf &out)
{
	RawArray *arrays[RawClf::kCount] = { &out.fids, &out.thrs, &out.child,
					     &out.hs, &out.weights, &out.depth };
	static const char *const names[RawClf::kCount] = { "fids", "thrs", "child",
							   "hs", "weights", "depth" };
	for (int i = 0; i < RawClf::kCount; i++) {
		Status s = readArray(clf, names[i], *arrays[i]);
		if (!s.ok())
			return s;
		if (arrays[i]->rows != out.fids.rows || arrays[i]->cols != out.fids.cols)
			return Status::error(ErrorCode::ModelInvalid,
					     "%s.%s is %zux%zu but %s.fids is %zux%zu", clf.path.c_str(),
					     names[i], arrays[i]->rows, arrays[i]->cols, clf.path.c_str(),
					     out.fids.rows, out.fids.cols);
	}
	if (out.fids.rows > kMaxNodes || out.fids.cols > kMaxTrees)
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s has %zu nodes x %zu trees; calped allows %zu x %zu",
				     clf.path.c_str(), out.fids.rows, out.fids.cols, kMaxNodes, kMaxTrees);
	return Status::success();
}

Status convertClf(const RawClf &raw, Model &model)
{
	const size_t nodes = raw.fids.rows;
	const size_t trees = raw.fids.cols;
	const size_t n = nodes * trees;
	model.nodesPerTree = static_cast<int32_t>(nodes);
	model.nTrees = static_cast<int32_t>(trees);
	model.fids.resize(n);
	model.thrs.resize(n);
	model.child.resize(n);
	model.hs.resize(n);
	for (size_t i = 0; i < n; i++) {
		uint32_t child = 0;
		double thr = 0, h = 0;
		Status s = toIndex(raw.fids, i, model.fids[i]);
		if (s.ok())
			s = toIndex(raw.child, i, child);
		if (s.ok())
			s = toFinite(raw.thrs, i, thr);
		if (s.ok())
			s = toFinite(raw.hs, i, h);
		if (!s.ok())
			return s;
		// 1-based left child; 1 would be the root itself and cannot be a child.
		if (child == 1)
			return Status::error(ErrorCode::ModelInvalid,
					     "clf.child(%zu, %zu) = 1 points at the root", i % nodes + 1,
					     i / nodes + 1);
		model.child[i] = child == 0 ? 0 : child - 1;
		model.thrs[i] = thresholdToFixed(thr);
		model.hs[i] = leafValueToFixed(h);
	}
	std::vector<int32_t> depth;
	int32_t deepest = 0;
	for (size_t t = 0; t < trees; t++) {
		int32_t treeDepth = 0;
		Status s = walkTree(model.child.data() + t * nodes, model.nodesPerTree,
				    static_cast<int32_t>(t), depth, treeDepth);
		if (s.ok())
			s = checkDepths(raw.depth, t * nodes, depth, static_cast<int32_t>(t));
		if (!s.ok())
			return s;
		if (treeDepth > deepest)
			deepest = treeDepth;
	}
	model.treeDepth = deepest;
	return Status::success();
}

} // namespace convert
} // namespace calped
