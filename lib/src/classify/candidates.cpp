// SPDX-License-Identifier: BSD-2-Clause
#include "classify/candidates.h"

#include <algorithm>
#include <new>

namespace calped {

Status Candidates::init(int capacity, const WindowBoxes &boxes, int lanes)
{
	map_ = boxes;
	count_ = 0;
	try {
		lanes_.clear();
		lanes_.resize(size_t(lanes));
		for (Lane &lane : lanes_)
			lane.hits.allocate(capacity, 1);
		boxes_.resize(size_t(capacity));
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "room for %d candidates", capacity);
	}
	return Status::success();
}

void Candidates::classify(const Classifier &classifier, const PyramidLevel &level,
			  const LevelChannels &channels, const uint32_t *listed, size_t count,
			  FrameStats &stats)
{
	lanes_[0].used = 0;
	const LevelHits hits = classifyInLane(0, classifier, level, channels, listed, count);
	gather(&hits, 1, stats);
}

void Candidates::emptyLanes()
{
	for (Lane &lane : lanes_)
		lane.used = 0;
}

LevelHits Candidates::classifyInLane(int laneIndex, const Classifier &classifier,
				     const PyramidLevel &level, const LevelChannels &channels,
				     const uint32_t *listed, size_t count)
{
	Lane &lane = lanes_[size_t(laneIndex)];
	LevelHits out;
	out.level = &level;
	out.lane = laneIndex;
	out.first = lane.used;
	const uint64_t room = uint64_t(boxes_.size() - lane.used);
	kernels::WindowHit *hits = lane.hits.data() + lane.used;
	if (listed) {
		out.passed = classifier.scanList(channels, listed, count, hits, room);
		out.windows = count;
	} else {
		out.passed = classifier.scan(channels, hits, room, &out.windows);
	}
	out.stored = std::min(out.passed, room);
	lane.used += size_t(out.stored);
	return out;
}

void Candidates::gather(const LevelHits *levels, int n, FrameStats &stats)
{
	// A lane holds its levels' first hits up to the capacity; since its levels come in
	// the gathering order, a level that did not fit in its lane is past the capacity here
	// too, so what is kept is what one thread would have kept.
	for (int l = 0; l < n; l++) {
		const LevelHits &h = levels[l];
		const kernels::WindowHit *hits = lanes_[size_t(h.lane)].hits.data() + h.first;
		const uint64_t room = uint64_t(capacity() - count_);
		const uint64_t kept = std::min(h.stored, room);
		for (uint64_t k = 0; k < kept; k++) {
			const WindowBox b = map_.box(*h.level, hits[k].row, hits[k].col);
			Detection &d = boxes_[size_t(count_++)];
			d = Detection();
			d.x = float(b.x);
			d.y = float(b.y);
			d.w = float(b.w);
			d.h = float(b.h);
			d.score = float(hits[k].score / double(1 << kScoreFracBits));
		}
		stats.windows += h.windows;
		stats.candidates += h.passed;
		stats.droppedWindows += h.passed - kept;
	}
}

} // namespace calped
