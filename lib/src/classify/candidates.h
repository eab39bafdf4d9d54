// SPDX-License-Identifier: BSD-2-Clause
// The windows of one frame that passed the cascade, as boxes in input-image pixels: what
// the search stage's classification yields and the suppression stage takes. Capacity
// fixed at setup; what does not fit is counted, never silently lost.
#pragma once

#include <calped/detector.h>
#include <calped/status.h>

#include <cstdint>
#include <vector>

#include "classify/classifier.h"
#include "core/plane.h"
#include "pyramid/pyramid.h"
#include "search/window_boxes.h"

namespace calped {

// What classifying one level left in a lane, for Candidates::gather().
struct LevelHits {
	const PyramidLevel *level = nullptr;
	int lane = 0;
	size_t first = 0;     // the level's first hit in its lane
	uint64_t passed = 0;  // windows that passed the cascade
	uint64_t stored = 0;  // of them, kept in the lane (the rest did not fit)
	uint64_t windows = 0; // windows evaluated
};

class Candidates
{
public:
	// lanes: threads that may classify at once (each fills its own lane of hits, each
	// lane holding `capacity`; untouched lanes cost no memory).
	Status init(int capacity, const WindowBoxes &boxes, int lanes = 1);
	void clear() { count_ = 0; }

	// Classifies every window of a level (`listed` null) or only the listed ones (row <<
	// 16 | column), keeps the hits as boxes and counts windows, candidates and drops.
	void classify(const Classifier &classifier, const PyramidLevel &level,
		      const LevelChannels &channels, const uint32_t *listed, size_t count,
		      FrameStats &stats);

	// The same in two steps, for levels classified on several threads at once: each
	// thread classifies into its own lane (after emptyLanes()), then gather() keeps the
	// hits in the order of the records given, exactly as classify() level after level
	// would (the first `capacity` hits; the rest counted as dropped).
	void emptyLanes();
	LevelHits classifyInLane(int lane, const Classifier &classifier, const PyramidLevel &level,
				 const LevelChannels &channels, const uint32_t *listed, size_t count);
	void gather(const LevelHits *levels, int count, FrameStats &stats);

	Detection *data() { return boxes_.data(); }
	int count() const { return count_; }
	int capacity() const { return int(boxes_.size()); }

private:
	struct Lane {
		PlaneBuffer<kernels::WindowHit> hits;
		size_t used = 0;
	};
	WindowBoxes map_;
	std::vector<Lane> lanes_;
	std::vector<Detection> boxes_;
	int count_ = 0;
};

} // namespace calped
