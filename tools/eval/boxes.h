// SPDX-License-Identifier: BSD-2-Clause
// Axis-aligned boxes in input-image pixels and their overlap (the thesis's eq. 4.1).
#pragma once

#include <vector>

namespace calped::eval_tool {

// Top-left corner and size.
struct Box {
	double x = 0, y = 0, w = 0, h = 0;
};

// A detection as the harness scores it.
struct ScoredBox {
	Box box;
	double score = 0;
};

// A ground-truth box; `ignore` boxes (MOTChallenge flag 0) are neither counted as ground
// truth nor turn a detection that matches them into a false positive.
struct GtBox {
	Box box;
	bool ignore = false;
};

// Detections of a sequence, index k holding frame k + 1.
using SequenceDetections = std::vector<std::vector<ScoredBox>>;

// Jaccard coefficient |A n B| / |A u B|; 0 when either box is empty.
double intersectionOverUnion(const Box &a, const Box &b);

} // namespace calped::eval_tool
