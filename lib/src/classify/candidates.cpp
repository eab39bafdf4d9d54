// SPDX-License-Identifier: BSD-2-Clause
#include "classify/candidates.h"

#include <algorithm>
#include <new>

namespace calped {

Status Candidates::init(int capacity, const WindowBoxes &boxes)
{
	map_ = boxes;
	count_ = 0;
	try {
		hits_.resize(size_t(capacity));
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
	const uint64_t room = uint64_t(capacity() - count_);
	uint64_t passed;
	if (listed) {
		passed = classifier.scanList(channels, listed, count, hits_.data(), room);
		stats.windows += count;
	} else {
		passed = classifier.scan(channels, hits_.data(), room, &stats.windows);
	}
	const uint64_t kept = std::min(passed, room);
	for (uint64_t k = 0; k < kept; k++) {
		const WindowBox b = map_.box(level, hits_[k].row, hits_[k].col);
		Detection &d = boxes_[size_t(count_++)];
		d = Detection();
		d.x = float(b.x);
		d.y = float(b.y);
		d.w = float(b.w);
		d.h = float(b.h);
		d.score = float(hits_[k].score / double(1 << kScoreFracBits));
	}
	stats.candidates += passed;
	stats.droppedWindows += passed - kept;
}

} // namespace calped
