// SPDX-License-Identifier: BSD-2-Clause
// Structure check of one boosted tree, shared by validateModel and the converter.
#pragma once

#include <cstdint>
#include <vector>

#include <calped/status.h>

namespace calped {

// Walks one tree of `nodesPerTree` nodes (child array as in calped::Model: 0 = leaf, else the
// 0-based left child, right child = left + 1). Fails with ModelInvalid, naming `tree` and
// the node, when a child index is not after its parent or runs past the tree, or when a
// reachable node has two parents. Children always come after their parent, so one pass in
// index order sees every parent before its children and no cycle can exist.
// On success depth[k] is node k's depth (-1 if unreachable from the root) and maxLeafDepth
// is the depth of the deepest reachable leaf.
Status walkTree(const uint32_t *child, int32_t nodesPerTree, int32_t tree,
		std::vector<int32_t> &depth, int32_t &maxLeafDepth);

} // namespace calped
