// SPDX-License-Identifier: BSD-2-Clause
#include "model/tree_walk.h"

#include <cstddef>

namespace calped {

Status walkTree(const uint32_t *child, int32_t nodesPerTree, int32_t tree,
		std::vector<int32_t> &depth, int32_t &maxLeafDepth)
{
	maxLeafDepth = 0;
	if (nodesPerTree <= 0)
		return Status::error(ErrorCode::ModelInvalid, "nodesPerTree = %d must be positive",
				     nodesPerTree);
	depth.assign(static_cast<size_t>(nodesPerTree), -1);
	depth[0] = 0;
	const uint32_t n = static_cast<uint32_t>(nodesPerTree);
	for (uint32_t k = 0; k < n; k++) {
		const uint32_t c = child[k];
		if (c == 0) {
			if (depth[k] > maxLeafDepth)
				maxLeafDepth = depth[k];
			continue;
		}
		if (c <= k)
			return Status::error(ErrorCode::ModelInvalid,
					     "child[tree %d, node %u] = %u does not come after its parent",
					     tree, k, c);
		if (c >= n - 1)
			return Status::error(ErrorCode::ModelInvalid,
					     "child[tree %d, node %u] = %u: right child %u is outside the %u-node tree",
					     tree, k, c, c + 1, n);
		if (depth[k] < 0)
			continue; // unreachable: its children stay unreachable too
		for (uint32_t side = 0; side < 2; side++) {
			if (depth[c + side] >= 0)
				return Status::error(ErrorCode::ModelInvalid,
						     "child[tree %d, node %u] = %u: node %u already has a parent",
						     tree, k, c, c + side);
			depth[c + side] = depth[k] + 1;
		}
	}
	return Status::success();
}

} // namespace calped
