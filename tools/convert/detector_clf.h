// SPDX-License-Identifier: BSD-2-Clause
// detector.clf (boosted trees, toolbox layout) -> calped::Model trees.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <calped/model.h>
#include <calped/status.h>

#include "mat_reader.h"

namespace calped {
namespace convert {

// One nodes x trees array exactly as stored in the .mat (column-major, i.e. tree by tree).
struct RawArray {
	std::string name;
	size_t rows = 0; // nodes per tree
	size_t cols = 0; // trees
	std::vector<double> values;
	NumberClass cls = NumberClass::Double;
};

struct RawClf {
	static constexpr int kCount = 6;
	RawArray fids, thrs, child, hs, weights, depth;

	// All six, in the order --dump-arrays writes them.
	void list(const RawArray *(&out)[kCount]) const
	{
		out[0] = &fids; out[1] = &thrs; out[2] = &child;
		out[3] = &hs; out[4] = &weights; out[5] = &depth;
	}
};

// Reads the six arrays and checks they share one nodes x trees shape within calped's limits.
Status readClf(const MatNode &clf, RawClf &out);

// Fills model's nTrees, nodesPerTree, treeDepth and arrays: toolbox child c -> c - 1,
// thresholds through thresholdToFixed, leaves through round(h * 2^16). Also checks that
// the toolbox's own depth array agrees with the tree walk on every reachable node.
Status convertClf(const RawClf &raw, Model &model);

} // namespace convert
} // namespace calped
