// SPDX-License-Identifier: BSD-2-Clause
// The libcamera port's frame queue without libcamera: the newest-frame drop policy, slot
// ownership, failures, sequence holes, timeouts, loss and halt, and a two-thread run in
// which every produced frame ends up delivered, dropped or incomplete.
#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "frame_queue.h"

namespace calped {
namespace ports {
namespace {

using Wait = FrameQueue::Wait;

TEST(LibcameraFrameQueue, ConsumerGetsTheNewestFrameAndOlderOnesAreRecycled)
{
	FrameQueue q;
	q.begin();
	EXPECT_EQ(q.completed(0, 10, 1000), -1); // nothing was waiting
	EXPECT_EQ(q.completed(1, 11, 2000), 0);  // frame 10 dropped, slot 0 back to the camera
	EXPECT_EQ(q.completed(2, 12, 3000), 1);  // frame 11 dropped
	FrameQueue::Taken t;
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	EXPECT_EQ(t.slot, 2);
	EXPECT_EQ(t.sequence, 12u);
	EXPECT_EQ(t.timestampNs, 3000);
	SourceStats s = q.stats();
	EXPECT_EQ(s.delivered, 1u);
	EXPECT_EQ(s.dropped, 2u);
	EXPECT_EQ(s.incomplete, 0u);
}

TEST(LibcameraFrameQueue, LentSlotStaysLentUntilGivenBack)
{
	FrameQueue q;
	q.begin();
	q.completed(3, 0, 0);
	FrameQueue::Taken t;
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	// New frames replace each other, never the lent one.
	EXPECT_EQ(q.completed(0, 1, 0), -1);
	EXPECT_EQ(q.completed(1, 2, 0), 0);
	EXPECT_EQ(q.giveBack(), 3);
	EXPECT_EQ(q.giveBack(), -1); // only once
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	EXPECT_EQ(t.slot, 1);
}

TEST(LibcameraFrameQueue, TimeoutIsCountedAndWaitsAboutAsLongAsAsked)
{
	FrameQueue q;
	q.begin();
	FrameQueue::Taken t;
	auto start = std::chrono::steady_clock::now();
	EXPECT_EQ(q.take(30, t), Wait::Timeout);
	auto waited = std::chrono::steady_clock::now() - start;
	EXPECT_GE(waited, std::chrono::milliseconds(30));
	EXPECT_EQ(q.take(0, t), Wait::Timeout);
	EXPECT_EQ(q.stats().timeouts, 2u);
	EXPECT_EQ(q.stats().delivered, 0u);
}

TEST(LibcameraFrameQueue, FailedAndCancelledBuffersAreIncompleteAndRequeued)
{
	FrameQueue q;
	q.begin();
	EXPECT_EQ(q.failed(2, 5), 2);
	EXPECT_EQ(q.cancelled(1), 1);
	EXPECT_EQ(q.completed(0, 6, 0), -1);
	SourceStats s = q.stats();
	EXPECT_EQ(s.incomplete, 2u);
	EXPECT_EQ(s.dropped, 0u); // 5 then 6: no hole
}

TEST(LibcameraFrameQueue, SequenceHolesCountAsDropped)
{
	FrameQueue q;
	q.begin();
	q.completed(0, 100, 0);
	FrameQueue::Taken t;
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	q.completed(1, 104, 0); // 101..103 never reached us
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	EXPECT_EQ(q.stats().dropped, 3u);
	// Across the 32-bit wrap.
	q.begin();
	q.completed(0, 0xffffffffu, 0);
	q.completed(1, 1, 0); // 0 missing; frame 0xffffffff replaced
	EXPECT_EQ(q.stats().dropped, 2u);
	// A counter that restarts is not a hole.
	q.begin();
	q.completed(0, 500, 0);
	q.completed(1, 0, 0);
	EXPECT_EQ(q.stats().dropped, 1u); // only the replaced frame
}

TEST(LibcameraFrameQueue, FailuresInARowBeyondTheLimitLoseTheCamera)
{
	FrameQueue q;
	q.begin("camera 'x'", 5);
	// A good frame resets the run.
	for (int i = 0; i < 4; ++i)
		EXPECT_EQ(q.failed(i % 4, 10 + i), i % 4);
	EXPECT_EQ(q.completed(0, 14, 0), -1);
	for (int i = 0; i < 4; ++i)
		EXPECT_EQ(q.cancelled(1), 1);
	FrameQueue::Taken t;
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	// The fifth in a row: lost, and its slot stays out.
	EXPECT_EQ(q.failed(2, 15), -1);
	EXPECT_EQ(q.take(0, t), Wait::Lost);
	EXPECT_STREQ(q.lostStatus().message(), "CameraLost: camera 'x' failed 5 frames in a row");
	EXPECT_EQ(q.stats().incomplete, 9u);
	// Without a limit, failures go on being recycled.
	q.begin();
	for (int i = 0; i < 1000; ++i)
		ASSERT_EQ(q.cancelled(3), 3);
}

TEST(LibcameraFrameQueue, ReachingTheFailureLimitWakesAWaitingConsumer)
{
	FrameQueue q;
	q.begin("camera 'y'", 3);
	std::thread camera([&] {
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
		for (int i = 0; i < 3; ++i)
			q.cancelled(i);
	});
	FrameQueue::Taken t;
	auto start = std::chrono::steady_clock::now();
	EXPECT_EQ(q.take(10000, t), Wait::Lost);
	EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
	camera.join();
}

TEST(LibcameraFrameQueue, LossWakesAWaitingConsumer)
{
	FrameQueue q;
	q.begin();
	std::thread camera([&] {
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
		q.lost(ErrorCode::CameraLost, "camera 'x' was disconnected");
	});
	FrameQueue::Taken t;
	auto start = std::chrono::steady_clock::now();
	EXPECT_EQ(q.take(10000, t), Wait::Lost);
	EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
	camera.join();
	Status st = q.lostStatus();
	EXPECT_EQ(st.code(), ErrorCode::CameraLost);
	EXPECT_STREQ(st.message(), "CameraLost: camera 'x' was disconnected");
	// After a loss nothing goes back to the camera, and later reasons do not replace the first.
	EXPECT_EQ(q.completed(0, 1, 0), -1);
	EXPECT_EQ(q.failed(1, 2), -1);
	q.lost(ErrorCode::CameraError, "later");
	EXPECT_EQ(q.lostStatus().code(), ErrorCode::CameraLost);
	EXPECT_EQ(q.take(0, t), Wait::Lost);
}

TEST(LibcameraFrameQueue, HaltIgnoresCancellationsOfStopAndWakesConsumer)
{
	FrameQueue q;
	q.begin();
	q.completed(0, 1, 0);
	FrameQueue::Taken t;
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	q.completed(1, 2, 0);
	q.halt();
	// What the camera cancels while stopping is neither counted nor requeued.
	EXPECT_EQ(q.cancelled(2), -1);
	EXPECT_EQ(q.cancelled(3), -1);
	EXPECT_EQ(q.giveBack(), -1);
	// A requeue refused by the stopping camera is no loss.
	q.lost(ErrorCode::CameraError, "camera 'x' refused a capture request");
	EXPECT_EQ(q.take(1000, t), Wait::Halted);
	EXPECT_EQ(q.stats().incomplete, 0u);
	EXPECT_EQ(q.lostStatus().code(), ErrorCode::Ok);
	// A new session starts clean.
	q.begin();
	EXPECT_EQ(q.stats().delivered, 0u);
	EXPECT_EQ(q.completed(2, 0, 0), -1);
	ASSERT_EQ(q.take(0, t), Wait::Frame);
	EXPECT_EQ(t.slot, 2);
}

// A camera thread completing frames into a 4-slot pool faster than a slow consumer takes
// them: slots are never lent twice or requeued while lent, and every frame is accounted for.
TEST(LibcameraFrameQueue, TwoThreadsEveryFrameAccountedFor)
{
	constexpr int kSlots = 4;
	constexpr uint32_t kFrames = 3000;
	FrameQueue q;
	q.begin();

	std::mutex poolMutex;
	std::vector<int> atCamera = { 0, 1, 2, 3 }; // slots the camera may fill
	std::atomic<bool> misuse{ false };
	std::atomic<uint32_t> produced{ 0 };
	std::atomic<bool> done{ false };

	std::thread camera([&] {
		for (uint32_t seq = 0; seq < kFrames; ++seq) {
			int slot = -1;
			while (slot < 0) {
				std::lock_guard<std::mutex> lock(poolMutex);
				if (!atCamera.empty()) {
					slot = atCamera.back();
					atCamera.pop_back();
				}
			}
			// Every 50th frame is damaged; every 7th sequence number is skipped.
			uint32_t number = seq + seq / 7;
			int back = seq % 50 == 49 ? q.failed(slot, number)
						  : q.completed(slot, number, int64_t(number));
			produced = number + 1;
			if (back >= 0) {
				std::lock_guard<std::mutex> lock(poolMutex);
				for (int s : atCamera)
					misuse = misuse || s == back;
				atCamera.push_back(back);
			}
			if (seq % 3 == 0)
				std::this_thread::yield();
		}
		done = true;
	});

	int lentBefore = -1;
	uint64_t lastSequence = 0;
	bool first = true;
	for (;;) {
		int back = q.giveBack();
		if (back >= 0) {
			EXPECT_EQ(back, lentBefore);
			std::lock_guard<std::mutex> lock(poolMutex);
			atCamera.push_back(back);
		}
		FrameQueue::Taken t;
		Wait w = q.take(200, t);
		if (w == Wait::Timeout) {
			if (!done)
				continue;
			// The camera finished; its last frame may have come after the wait ended.
			if ((w = q.take(0, t)) == Wait::Timeout)
				break;
		}
		ASSERT_EQ(w, Wait::Frame);
		ASSERT_GE(t.slot, 0);
		ASSERT_LT(t.slot, kSlots);
		{
			std::lock_guard<std::mutex> lock(poolMutex);
			for (int s : atCamera) {
				ASSERT_NE(s, t.slot) << "lent slot is also queued at the camera";
			}
		}
		if (!first) {
			EXPECT_GT(t.sequence, lastSequence); // newest first, never backwards
		}
		first = false;
		lastSequence = t.sequence;
		lentBefore = t.slot;
		std::this_thread::sleep_for(std::chrono::microseconds(300)); // a slow detector
	}
	camera.join();
	EXPECT_FALSE(misuse);

	SourceStats s = q.stats();
	EXPECT_GT(s.delivered, 0u);
	EXPECT_GT(s.dropped, 0u);
	EXPECT_EQ(s.incomplete, kFrames / 50);
	// Sequence numbers 0..produced-1: each one delivered, dropped (replaced or a hole) or
	// incomplete.
	EXPECT_EQ(s.delivered + s.dropped + s.incomplete, uint64_t(produced));
}

} // namespace
} // namespace ports
} // namespace calped
