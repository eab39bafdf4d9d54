// SPDX-License-Identifier: BSD-2-Clause
// Hands completed capture buffers from the camera's thread to one consumer thread, with the
// drop policy "newest frame wins". Buffers are slots 0..N-1 of a fixed pool. A slot is in
// exactly one place: queued at the camera, waiting here (at most one), or lent to the
// consumer (at most one).
//
//   completed(slot)  a frame arrived. If another frame was already waiting, the older one
//                    is dropped (counted) and its slot is returned so the caller requeues it
//                    at the camera at once: the consumer always gets the newest frame and the
//                    camera keeps N-2 buffers to fill.
//   failed/cancelled a damaged or cancelled buffer: counted as incomplete, slot returned for
//                    requeueing (none after halt(), when the camera is being stopped).
//                    After `failureLimit` of them in a row the camera counts as lost: a
//                    broken pipeline would otherwise cancel and get back its requests forever.
//   take()           waits for the waiting frame and lends it; giveBack() returns the lent
//                    slot for requeueing.
//
// Holes in the camera's frame sequence numbers (frames the driver had no buffer for) are
// counted as dropped too, so every frame the camera produced is delivered, dropped or
// incomplete. Nothing here allocates after construction; independent of libcamera, so the
// policy is tested without a camera.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>

#include <calped/status.h>

#include "frame_source.h"

namespace calped {
namespace ports {

class FrameQueue
{
public:
	struct Taken {
		int slot = -1;
		uint32_t sequence = 0;
		int64_t timestampNs = 0;
	};
	enum class Wait { Frame, Timeout, Lost, Halted };

	FrameQueue() = default;

	// Starts a streaming session: nothing waiting or lent, counters zero. `label` names the
	// camera in the failure-limit message; failureLimit 0 means no limit.
	void begin(const char *label = "camera", int failureLimit = 0);
	// The camera is being stopped: from now on completions are neither counted nor returned
	// for requeueing, and take() returns Halted. Once the camera has stopped, every slot is
	// the caller's again (the waiting and lent frames are forgotten).
	void halt();

	// Camera thread. Each returns a slot to requeue now, or -1.
	int completed(int slot, uint32_t sequence, int64_t timestampNs);
	int failed(int slot, uint32_t sequence);
	int cancelled(int slot);
	// The camera disappeared or refused a buffer: take() returns Lost from now on. The first
	// reason is kept; `why` is copied. Ignored after halt() (a stopping camera refuses
	// buffers).
	void lost(ErrorCode code, const char *why);

	// Consumer thread.
	Wait take(int timeoutMs, Taken &out);
	int giveBack();
	// After take() returned Lost: the reason.
	Status lostStatus() const;

	SourceStats stats() const;

private:
	void noteSequence(uint32_t sequence);
	// Counts one incomplete frame; false when that reaches the failure limit (then lost).
	bool noteFailure();
	void loseLocked(ErrorCode code, const char *why);

	mutable std::mutex mutex_;
	std::condition_variable ready_;
	bool streaming_ = false;
	bool halted_ = false;
	bool lost_ = false;
	ErrorCode lostCode_ = ErrorCode::Ok;
	char lostWhy_[200] = "";
	Taken waiting_;
	int lent_ = -1;
	char label_[160] = "camera";
	int failureLimit_ = 0;
	int failuresInARow_ = 0;
	bool haveSequence_ = false;
	uint32_t lastSequence_ = 0;
	SourceStats stats_;
};

} // namespace ports
} // namespace calped
