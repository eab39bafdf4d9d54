// SPDX-License-Identifier: BSD-2-Clause
#include "frame_numbers.h"

namespace calped {
namespace ports {

namespace {

// How far `id` is ahead of `last` (negative: behind). Two 16-bit ids are on a circle of
// 65535 (id 0 is not used): 65535 -> 1 is +1, 2 -> 65534 is -3. Anything else (64-bit ids,
// or a camera that does send 0) is plain subtraction.
int64_t distance(uint64_t last, uint64_t id)
{
	constexpr int64_t kCircle = 65535;
	const bool shortIds = last >= 1 && last <= 0xffff && id >= 1 && id <= 0xffff;
	int64_t d = static_cast<int64_t>(id - last); // two's complement: ids far apart stay exact
	if (shortIds) {
		if (d > kCircle / 2)
			d -= kCircle;
		else if (d < -kCircle / 2)
			d += kCircle;
	}
	return d;
}

} // namespace

uint64_t FrameNumbers::next(uint64_t blockId, int64_t timestampNs)
{
	if (!started_) {
		// The first frame keeps the camera's id, so numbers equal block ids until a wrap.
		started_ = true;
		restarted_ = false;
		lastId_ = blockId;
		number_ = blockId;
		lastTimestampNs_ = timestampNs;
		return number_;
	}
	int64_t step = 1;
	if (restarted_) {
		restarted_ = false;
		// The ids start afresh: the frames the camera made while it was away are estimated
		// from the time since the last frame and the frame interval seen before.
		if (timestampNs > 0 && lastTimestampNs_ > 0 && intervalNs_ > 0 && timestampNs > lastTimestampNs_) {
			const double frames = double(timestampNs - lastTimestampNs_) / intervalNs_;
			const int64_t lost = static_cast<int64_t>(frames + 0.5) - 1;
			if (lost > 0) {
				lostAcrossRestarts_ += static_cast<uint64_t>(lost);
				unseen_ += static_cast<uint64_t>(lost);
				step += lost;
			}
		}
	} else {
		const int64_t d = distance(lastId_, blockId);
		if (d > 1)
			unseen_ += static_cast<uint64_t>(d - 1);
		if (d > 0)
			step = d;
		// The interval per id step, smoothed (a quarter of each new measure).
		if (d > 0 && timestampNs > 0 && lastTimestampNs_ > 0 && timestampNs > lastTimestampNs_) {
			const double measured = double(timestampNs - lastTimestampNs_) / double(d);
			intervalNs_ = intervalNs_ > 0 ? intervalNs_ + (measured - intervalNs_) / 4 : measured;
		}
	}
	lastId_ = blockId;
	if (timestampNs > 0)
		lastTimestampNs_ = timestampNs;
	number_ += static_cast<uint64_t>(step);
	return number_;
}

} // namespace ports
} // namespace calped
