// SPDX-License-Identifier: BSD-2-Clause
// The libcamera port's per-frame bookkeeping allocates nothing: the frame queue's calls
// on both threads, timeouts and the stats. This binary links tests/common/alloc_counter.cpp
// (a replaced operator new that counts calls), like tests/core/alloc_test.cpp.
#include <gtest/gtest.h>

#include "common/alloc_counter.h"
#include "frame_queue.h"

namespace calped {
namespace ports {
namespace {

TEST(LibcameraQueueAllocations, PerFrameCallsAllocateNothing)
{
	FrameQueue q;
	q.begin("camera 'z'", 64);
	FrameQueue::Taken t;
	uint32_t sequence = 0;
	test::startCountingAllocations();
	for (int i = 0; i < 1000; ++i) {
		q.completed(i % 4, sequence++, i);
		if (i % 10 == 0)
			q.failed((i + 1) % 4, sequence++);
		if (i % 17 == 0)
			q.cancelled((i + 2) % 4);
		if (q.take(0, t) != FrameQueue::Wait::Frame)
			ADD_FAILURE() << "no frame at " << i;
		q.giveBack();
		q.take(0, t); // nothing waiting: a counted timeout
		(void)q.stats();
	}
	EXPECT_EQ(test::stopCountingAllocations(), 0);
	EXPECT_EQ(q.stats().delivered, 1000u);
	EXPECT_EQ(q.stats().timeouts, 1000u);
}

TEST(LibcameraQueueAllocations, LossAndItsStatusAllocateNothing)
{
	FrameQueue q;
	q.begin();
	test::startCountingAllocations();
	q.lost(ErrorCode::CameraLost, "camera '/base/soc/i2c0mux/i2c@1/imx219@10' was disconnected");
	FrameQueue::Taken t;
	FrameQueue::Wait w = q.take(1000, t);
	Status st = q.lostStatus();
	q.halt();
	const long seen = test::stopCountingAllocations();
	EXPECT_EQ(w, FrameQueue::Wait::Lost);
	EXPECT_EQ(st.code(), ErrorCode::CameraLost);
	EXPECT_EQ(seen, 0);
}

} // namespace
} // namespace ports
} // namespace calped
