// SPDX-License-Identifier: BSD-2-Clause
#include "suppress/suppression.h"

#include <cmath>
#include <new>

#include "suppress/nms.h"

namespace calped {

Status Suppression::init(const ModelParams &params, bool nms, bool boxVoting, bool scoreRatio,
			 int capacity)
{
	// Without NMS the greedy pass keeps everything (nothing overlaps more than infinity)
	// but still sorts by score, as the toolbox's output is.
	overlap_ = nms ? params.nmsOverlap : INFINITY;
	useUnion_ = params.nmsOverlapDenominator == NmsOverlapDenominator::Union;
	boxVoting_ = boxVoting;
	scoreRatio_ = scoreRatio;
	try {
		sorted_.resize(size_t(capacity));
		order_.resize(size_t(capacity));
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "suppression scratch");
	}
	return Status::success();
}

int Suppression::run(Detection *boxes, int count)
{
	int kept = nmsGreedy(boxes, count, overlap_, useUnion_, order_.data(), sorted_.data());
	// Voting reads every candidate, which NMS left sorted in sorted_.
	if (boxVoting_)
		voteBoxes(boxes, kept, sorted_.data(), count, 0.6f);
	if (scoreRatio_)
		kept = suppressByScoreRatio(boxes, kept, order_.data());
	return kept;
}

} // namespace calped
