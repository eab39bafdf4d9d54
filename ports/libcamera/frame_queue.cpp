// SPDX-License-Identifier: BSD-2-Clause
#include "frame_queue.h"

#include <chrono>
#include <cstdio>

namespace calped {
namespace ports {

void FrameQueue::begin(const char *label, int failureLimit)
{
	std::lock_guard<std::mutex> lock(mutex_);
	std::snprintf(label_, sizeof(label_), "%s", label);
	failureLimit_ = failureLimit;
	failuresInARow_ = 0;
	streaming_ = true;
	halted_ = false;
	lost_ = false;
	lostCode_ = ErrorCode::Ok;
	lostWhy_[0] = '\0';
	waiting_ = Taken();
	lent_ = -1;
	haveSequence_ = false;
	lastSequence_ = 0;
	stats_ = SourceStats();
}

void FrameQueue::halt()
{
	{
		std::lock_guard<std::mutex> lock(mutex_);
		streaming_ = false;
		halted_ = true;
		waiting_ = Taken();
		lent_ = -1;
	}
	ready_.notify_all();
}

// Sequence numbers grow by one per frame the sensor produced; a hole is frames the driver
// had no buffer for. Wrap-around of the 32-bit counter is handled by unsigned arithmetic.
void FrameQueue::noteSequence(uint32_t sequence)
{
	if (haveSequence_) {
		uint32_t step = sequence - lastSequence_;
		// A step of 0 or a huge one (the counter went backwards) is not a hole.
		if (step > 1 && step < (1u << 30))
			stats_.dropped += step - 1;
	}
	haveSequence_ = true;
	lastSequence_ = sequence;
}

bool FrameQueue::noteFailure()
{
	++stats_.incomplete;
	if (failureLimit_ <= 0 || ++failuresInARow_ < failureLimit_)
		return true;
	char why[sizeof(label_) + 48];
	std::snprintf(why, sizeof(why), "%s failed %d frames in a row", label_, failuresInARow_);
	loseLocked(ErrorCode::CameraLost, why);
	return false;
}

int FrameQueue::completed(int slot, uint32_t sequence, int64_t timestampNs)
{
	int requeue = -1;
	{
		std::lock_guard<std::mutex> lock(mutex_);
		if (!streaming_)
			return -1;
		failuresInARow_ = 0;
		noteSequence(sequence);
		if (waiting_.slot >= 0) {
			++stats_.dropped;
			requeue = waiting_.slot;
		}
		waiting_ = Taken{ slot, sequence, timestampNs };
	}
	ready_.notify_one();
	return requeue;
}

int FrameQueue::failed(int slot, uint32_t sequence)
{
	bool keepGoing;
	{
		std::lock_guard<std::mutex> lock(mutex_);
		if (!streaming_)
			return -1;
		noteSequence(sequence);
		keepGoing = noteFailure();
	}
	if (!keepGoing)
		ready_.notify_all();
	return keepGoing ? slot : -1;
}

int FrameQueue::cancelled(int slot)
{
	bool keepGoing;
	{
		std::lock_guard<std::mutex> lock(mutex_);
		if (!streaming_)
			return -1;
		keepGoing = noteFailure();
	}
	if (!keepGoing)
		ready_.notify_all();
	return keepGoing ? slot : -1;
}

void FrameQueue::loseLocked(ErrorCode code, const char *why)
{
	// While the camera stops it refuses requeued buffers; that is no loss.
	if (halted_)
		return;
	if (!lost_) {
		lost_ = true;
		lostCode_ = code;
		std::snprintf(lostWhy_, sizeof(lostWhy_), "%s", why);
	}
	streaming_ = false;
}

void FrameQueue::lost(ErrorCode code, const char *why)
{
	{
		std::lock_guard<std::mutex> lock(mutex_);
		loseLocked(code, why);
	}
	ready_.notify_all();
}

FrameQueue::Wait FrameQueue::take(int timeoutMs, Taken &out)
{
	std::unique_lock<std::mutex> lock(mutex_);
	auto settled = [this] { return lost_ || halted_ || waiting_.slot >= 0; };
	if (!ready_.wait_for(lock, std::chrono::milliseconds(timeoutMs < 0 ? 0 : timeoutMs),
			     settled)) {
		++stats_.timeouts;
		return Wait::Timeout;
	}
	if (lost_)
		return Wait::Lost;
	if (halted_)
		return Wait::Halted;
	out = waiting_;
	waiting_ = Taken();
	lent_ = out.slot;
	++stats_.delivered;
	return Wait::Frame;
}

int FrameQueue::giveBack()
{
	std::lock_guard<std::mutex> lock(mutex_);
	int slot = lent_;
	lent_ = -1;
	// After a loss or halt the camera takes nothing back.
	return streaming_ ? slot : -1;
}

Status FrameQueue::lostStatus() const
{
	std::lock_guard<std::mutex> lock(mutex_);
	if (!lost_)
		return Status::success();
	return Status::error(lostCode_, "%s", lostWhy_);
}

SourceStats FrameQueue::stats() const
{
	std::lock_guard<std::mutex> lock(mutex_);
	return stats_;
}

} // namespace ports
} // namespace calped
