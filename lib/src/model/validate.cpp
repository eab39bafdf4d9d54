// SPDX-License-Identifier: BSD-2-Clause
// validateModel: everything the detector may rely on once a model has been accepted.
// The ranges are listed, with reasons, in docs/model-format.md.
#include <calped/model.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <vector>

#include "model/blob_format.h"
#include "model/tree_walk.h"

namespace calped {

int32_t Model::classifierShrink() const
{
	return params.nFilters > 0 ? 2 * params.shrink : params.shrink;
}

int32_t Model::classifierChannels() const
{
	return params.nFilters > 0 ? 10 * params.nFilters : 10;
}

int32_t Model::featureCount() const
{
	const ModelParams &p = params;
	const int32_t shrink = classifierShrink();
	if (shrink <= 0 || p.modelDsPadH <= 0 || p.modelDsPadW <= 0 || p.nFilters < 0 ||
	    p.nFilters > blob::kMaxFilters)
		return 0;
	// 3 LUV + 1 gradient magnitude + 6 orientation channels (each nFilters times for LDCF).
	const int64_t count = static_cast<int64_t>(p.modelDsPadH / shrink) *
			      (p.modelDsPadW / shrink) * classifierChannels();
	if (count > std::numeric_limits<int32_t>::max())
		return 0;
	return static_cast<int32_t>(count);
}

namespace {

Status invalid(const char *field, int32_t value, const char *rule)
{
	return Status::error(ErrorCode::ModelInvalid, "%s = %d %s", field, value, rule);
}

Status invalidFloat(const char *field, float value, const char *rule)
{
	return Status::error(ErrorCode::ModelInvalid, "%s = %.9g %s", field, value, rule);
}

bool inRange(int32_t v, int32_t lo, int32_t hi) { return v >= lo && v <= hi; }

// Finite and inside [lo, hi].
bool inRange(float v, float lo, float hi) { return std::isfinite(v) && v >= lo && v <= hi; }

Status validateGeometry(const ModelParams &p)
{
	// shrink first: every other geometric rule is relative to it.
	if (p.shrink <= 0)
		return invalid("shrink", p.shrink, "must be positive");
	if (p.shrink != 2 && p.shrink != 4)
		return Status::error(ErrorCode::ModelUnsupported,
				     "shrink = %d is not supported (calped handles 4 and 2)", p.shrink);
	if (!inRange(p.modelDsPadH, p.shrink, 1024) || p.modelDsPadH % p.shrink != 0)
		return invalid("modelDsPadH", p.modelDsPadH, "must be a multiple of shrink in [shrink, 1024]");
	if (!inRange(p.modelDsPadW, p.shrink, 1024) || p.modelDsPadW % p.shrink != 0)
		return invalid("modelDsPadW", p.modelDsPadW, "must be a multiple of shrink in [shrink, 1024]");
	// At least one cell: a smaller window gives boxes of no height (1e-30 would pass > 0).
	if (!(std::isfinite(p.modelDsH) && p.modelDsH >= p.shrink && p.modelDsH <= p.modelDsPadH))
		return invalidFloat("modelDsH", p.modelDsH, "must be in [shrink, modelDsPadH]");
	if (!(std::isfinite(p.modelDsW) && p.modelDsW >= p.shrink && p.modelDsW <= p.modelDsPadW))
		return invalidFloat("modelDsW", p.modelDsW, "must be in [shrink, modelDsPadW]");
	if (!inRange(p.stride, p.shrink, 1024) || p.stride % p.shrink != 0)
		return invalid("stride", p.stride, "must be a positive multiple of shrink, at most 1024");
	// |cascThr| * 2^16 must fit in int32 so the detector can compare in score fixed point.
	if (!inRange(p.cascThr, -32767.0f, 32767.0f))
		return invalidFloat("cascThr", p.cascThr, "must be finite, within +-32767");
	return Status::success();
}

Status validateChannels(const ModelParams &p)
{
	if (!inRange(p.colorSmooth, 0, 16))
		return invalid("colorSmooth", p.colorSmooth, "must be in [0, 16]");
	if (!inRange(p.gradNormRad, 0, 32))
		return invalid("gradNormRad", p.gradNormRad, "must be in [0, 32]");
	if (!(std::isfinite(p.gradNormConst) && p.gradNormConst > 0))
		return invalidFloat("gradNormConst", p.gradNormConst, "must be finite and > 0");
	if (!inRange(p.gradColorChn, 0, 3))
		return invalid("gradColorChn", p.gradColorChn, "must be in [0, 3]");
	if (!inRange(p.gradFull, 0, 1))
		return invalid("gradFull", p.gradFull, "must be 0 or 1");
	if (!inRange(p.histBinSize, 1, 32))
		return invalid("histBinSize", p.histBinSize, "must be in [1, 32]");
	if (p.nOrients <= 0)
		return invalid("nOrients", p.nOrients, "must be positive");
	if (p.nOrients != 6)
		return Status::error(ErrorCode::ModelUnsupported,
				     "nOrients = %d is not supported (calped's 10 channels need 6)",
				     p.nOrients);
	// The toolbox only looks at softBin's sign and parity; the converter canonicalises it.
	if (!inRange(p.softBin, -2, 1))
		return invalid("softBin", p.softBin, "must be in [-2, 1]");
	if (p.toolboxCpu != ToolboxCpu::Intel && p.toolboxCpu != ToolboxCpu::AmdEpyc)
		return invalid("toolboxCpu", int(p.toolboxCpu), "must be Intel (0) or AmdEpyc (1)");
	return Status::success();
}

Status validatePyramid(const ModelParams &p)
{
	if (!inRange(p.nPerOct, 1, 64))
		return invalid("nPerOct", p.nPerOct, "must be in [1, 64]");
	if (!inRange(p.nOctUp, 0, 4))
		return invalid("nOctUp", p.nOctUp, "must be in [0, 4]");
	if (!inRange(p.nApprox, 0, 4 * p.nPerOct))
		return invalid("nApprox", p.nApprox, "must be in [0, 4 * nPerOct]");
	static const char *const lambdaNames[3] = { "lambdas[0]", "lambdas[1]", "lambdas[2]" };
	for (int i = 0; i < 3; i++)
		if (!inRange(p.lambdas[i], -2.0f, 2.0f))
			return invalidFloat(lambdaNames[i], p.lambdas[i], "must be finite, in [-2, 2]");
	if (!inRange(p.padH, 0, 1024) || p.padH % p.shrink != 0)
		return invalid("padH", p.padH, "must be a multiple of shrink in [0, 1024]");
	if (!inRange(p.padW, 0, 1024) || p.padW % p.shrink != 0)
		return invalid("padW", p.padW, "must be a multiple of shrink in [0, 1024]");
	if (!(std::isfinite(p.minDsH) && p.minDsH > 0 && p.minDsH <= 4096))
		return invalidFloat("minDsH", p.minDsH, "must be in (0, 4096]");
	if (!(std::isfinite(p.minDsW) && p.minDsW > 0 && p.minDsW <= 4096))
		return invalidFloat("minDsW", p.minDsW, "must be in (0, 4096]");
	if (!inRange(p.pyramidSmooth, 0, 16))
		return invalid("pyramidSmooth", p.pyramidSmooth, "must be in [0, 16]");
	return Status::success();
}

// LDCF's filters: shape, weights, and a window that is whole cells after the halving.
Status validateFilters(const Model &m)
{
	const ModelParams &p = m.params;
	if (!inRange(p.nFilters, 0, blob::kMaxFilters))
		return invalid("nFilters", p.nFilters, "must be in [0, 16]");
	if (p.nFilters == 0) {
		if (p.filterSize != 0)
			return invalid("filterSize", p.filterSize, "must be 0 when nFilters is 0");
		if (!m.filters.empty())
			return Status::error(ErrorCode::ModelInvalid,
					     "filters has %zu weights but nFilters is 0", m.filters.size());
		return Status::success();
	}
	if (!inRange(p.filterSize, 1, blob::kMaxFilterSize) || p.filterSize % 2 == 0)
		return invalid("filterSize", p.filterSize, "must be odd, in [1, 15], with filters");
	const size_t count = size_t(p.nFilters) * 10 * size_t(p.filterSize) * size_t(p.filterSize);
	if (m.filters.size() != count)
		return Status::error(ErrorCode::ModelInvalid,
				     "filters has %zu weights, nFilters %d x 10 x %d x %d = %zu",
				     m.filters.size(), p.nFilters, p.filterSize, p.filterSize, count);
	for (size_t i = 0; i < count; i++)
		if (!inRange(m.filters[i], -blob::kMaxFilterWeight, blob::kMaxFilterWeight))
			return Status::error(ErrorCode::ModelInvalid,
					     "filters[%zu] = %d is outside [-32768, 32768] (|weight| <= 1 in Q15)",
					     i, m.filters[i]);
	// The trees read cells of twice the shrink: the window and its stride must be whole ones.
	const int32_t cell = 2 * p.shrink;
	if (p.modelDsPadH % cell != 0)
		return invalid("modelDsPadH", p.modelDsPadH, "must be a multiple of 2 * shrink with filters");
	if (p.modelDsPadW % cell != 0)
		return invalid("modelDsPadW", p.modelDsPadW, "must be a multiple of 2 * shrink with filters");
	if (p.stride % cell != 0)
		return invalid("stride", p.stride, "must be a multiple of 2 * shrink with filters");
	return Status::success();
}

Status validateNms(const ModelParams &p)
{
	if (!(std::isfinite(p.nmsOverlap) && p.nmsOverlap > 0 && p.nmsOverlap <= 1))
		return invalidFloat("nmsOverlap", p.nmsOverlap, "must be in (0, 1]");
	const uint32_t dnm = static_cast<uint32_t>(p.nmsOverlapDenominator);
	if (dnm != static_cast<uint32_t>(NmsOverlapDenominator::Min) &&
	    dnm != static_cast<uint32_t>(NmsOverlapDenominator::Union))
		return Status::error(ErrorCode::ModelInvalid,
				     "nmsOverlapDenominator = %u must be 0 (Min) or 1 (Union)", dnm);
	return Status::success();
}

Status validateName(const std::string &name)
{
	if (name.size() > blob::kMaxNameLength)
		return Status::error(ErrorCode::ModelInvalid, "name length = %zu exceeds %u bytes",
				     name.size(), blob::kMaxNameLength);
	for (size_t i = 0; i < name.size(); i++) {
		const unsigned char c = static_cast<unsigned char>(name[i]);
		if (c < 0x20 || c == 0x7F)
			return Status::error(ErrorCode::ModelInvalid,
					     "name byte %zu = 0x%02X is a control character", i, c);
	}
	return Status::success();
}

Status validateShape(const Model &m)
{
	if (!inRange(m.nTrees, 1, blob::kMaxTrees))
		return invalid("nTrees", m.nTrees, "must be in [1, 65536]");
	if (!inRange(m.nodesPerTree, 1, blob::kMaxNodesPerTree))
		return invalid("nodesPerTree", m.nodesPerTree, "must be in [1, 255]");
	if (!inRange(m.treeDepth, 0, blob::kMaxTreeDepth))
		return invalid("treeDepth", m.treeDepth, "must be in [0, 8]");
	const size_t n = static_cast<size_t>(m.nTrees) * static_cast<size_t>(m.nodesPerTree);
	const struct {
		const char *name;
		size_t size;
	} arrays[4] = { { "fids", m.fids.size() }, { "thrs", m.thrs.size() },
			{ "child", m.child.size() }, { "hs", m.hs.size() } };
	for (const auto &a : arrays)
		if (a.size != n)
			return Status::error(ErrorCode::ModelInvalid,
					     "%s has %zu entries, nTrees * nodesPerTree = %zu",
					     a.name, a.size, n);
	return Status::success();
}

// Tree structure, feature indices, depth and the score range, tree by tree.
Status validateTrees(const Model &m)
{
	const uint32_t features = static_cast<uint32_t>(m.featureCount());
	const size_t nodes = static_cast<size_t>(m.nodesPerTree);
	std::vector<int32_t> depth;
	int32_t deepest = 0;
	int64_t scoreBound = 0; // sum over trees of the largest |leaf| reachable
	for (int32_t t = 0; t < m.nTrees; t++) {
		const size_t base = static_cast<size_t>(t) * nodes;
		int32_t treeDepth = 0;
		Status s = walkTree(m.child.data() + base, m.nodesPerTree, t, depth, treeDepth);
		if (!s.ok())
			return s;
		if (treeDepth > blob::kMaxTreeDepth)
			return Status::error(ErrorCode::ModelInvalid,
					     "treeDepth: tree %d has a leaf at depth %d, more than %d",
					     t, treeDepth, blob::kMaxTreeDepth);
		if (treeDepth > deepest)
			deepest = treeDepth;
		int64_t largestLeaf = 0;
		for (size_t k = 0; k < nodes; k++) {
			// Leaf fids are never read; they are held to the same bound so that no stored
			// index can point outside a window.
			if (m.fids[base + k] >= features)
				return Status::error(ErrorCode::ModelInvalid,
						     "fids[tree %d, node %zu] = %u is not below featureCount %u",
						     t, k, m.fids[base + k], features);
			if (m.child[base + k] == 0 && depth[k] >= 0) {
				const int64_t h = m.hs[base + k];
				const int64_t magnitude = h < 0 ? -h : h;
				if (magnitude > largestLeaf)
					largestLeaf = magnitude;
			}
		}
		scoreBound += largestLeaf;
	}
	if (deepest != m.treeDepth)
		return Status::error(ErrorCode::ModelInvalid,
				     "treeDepth = %d but the deepest leaf is at depth %d",
				     m.treeDepth, deepest);
	// Any partial sum of leaves is bounded by this, so an int32 running score cannot overflow.
	if (scoreBound > std::numeric_limits<int32_t>::max())
		return Status::error(ErrorCode::ModelInvalid,
				     "hs: the largest leaves of all trees sum to %lld, beyond int32",
				     static_cast<long long>(scoreBound));
	return Status::success();
}

} // namespace

Status validateModel(const Model &model)
{
	try {
		Status s = validateName(model.name);
		if (s.ok())
			s = validateGeometry(model.params);
		if (s.ok())
			s = validateChannels(model.params);
		if (s.ok())
			s = validatePyramid(model.params);
		if (s.ok())
			s = validateNms(model.params);
		if (s.ok())
			s = validateFilters(model);
		if (s.ok())
			s = validateShape(model);
		if (s.ok())
			s = validateTrees(model);
		return s;
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "validating the model's trees");
	}
}

} // namespace calped
