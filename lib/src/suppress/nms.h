// SPDX-License-Identifier: BSD-2-Clause
// Greedy non-maximum suppression (the toolbox's bbNms type 'maxg').
#pragma once

#include <calped/detector.h>

namespace calped {

// Sorts `boxes` by descending score (ties keep their order) and removes, greedily, every
// box whose overlap with a kept higher-scoring box exceeds `overlap`; overlap is the
// intersection over the smaller box's area (useUnion false) or over the union.
// `order` and `keep` are scratch of n elements. Returns the number of boxes kept,
// compacted to the front of `boxes` in score order.
int nmsGreedy(Detection *boxes, int n, float overlap, bool useUnion, int *order, Detection *tmp);

// The thesis's second suppression step (3.3), on boxes sorted by descending score: a box
// is removed when its overlap (intersection over union) with a kept higher-scoring box
// exceeds the ratio of their scores. keep is scratch of n ints. Returns the boxes kept.
int suppressByScoreRatio(Detection *boxes, int n, int *keep);

// Box voting (Gidaris and Komodakis, ICCV 2015): each kept box becomes the mean of the
// candidates overlapping it at IoU > minIou (itself included), weighted by score^4;
// candidates scoring <= 0 weigh nothing. Scores are unchanged. The greedy NMS keeps the
// best-scoring window, whose position the classifier knows only to a few pixels; its
// strong neighbours agree on where the person is.
void voteBoxes(Detection *kept, int nKept, const Detection *candidates, int nCandidates,
	       float minIou);

} // namespace calped
