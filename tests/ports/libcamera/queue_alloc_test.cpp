// SPDX-License-Identifier: BSD-2-Clause
// The libcamera port's per-frame bookkeeping allocates nothing: the frame queue's calls
// on both threads, timeouts and the stats. This binary replaces the global allocation
// functions to count calls (like tests/core/alloc_test.cpp).
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "frame_queue.h"

namespace {
std::atomic<bool> counting{ false };
std::atomic<long> allocations{ 0 };

void *countedAlloc(size_t size)
{
	if (counting.load())
		allocations++;
	void *p = std::malloc(size ? size : 1);
	if (!p)
		throw std::bad_alloc();
	return p;
}
} // namespace

void *operator new(size_t size) { return countedAlloc(size); }
void *operator new[](size_t size) { return countedAlloc(size); }
void *operator new(size_t size, const std::nothrow_t &) noexcept
{
	try {
		return countedAlloc(size);
	} catch (...) {
		return nullptr;
	}
}
void *operator new[](size_t size, const std::nothrow_t &t) noexcept { return operator new(size, t); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, size_t) noexcept { std::free(p); }
void operator delete[](void *p, size_t) noexcept { std::free(p); }

namespace calped {
namespace ports {
namespace {

TEST(LibcameraQueueAllocations, PerFrameCallsAllocateNothing)
{
	FrameQueue q;
	q.begin("camera 'z'", 64);
	FrameQueue::Taken t;
	uint32_t sequence = 0;
	allocations = 0;
	counting = true;
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
	counting = false;
	EXPECT_EQ(allocations.load(), 0);
	EXPECT_EQ(q.stats().delivered, 1000u);
	EXPECT_EQ(q.stats().timeouts, 1000u);
}

TEST(LibcameraQueueAllocations, LossAndItsStatusAllocateNothing)
{
	FrameQueue q;
	q.begin();
	allocations = 0;
	counting = true;
	q.lost(ErrorCode::CameraLost, "camera '/base/soc/i2c0mux/i2c@1/imx219@10' was disconnected");
	FrameQueue::Taken t;
	FrameQueue::Wait w = q.take(1000, t);
	Status st = q.lostStatus();
	q.halt();
	counting = false;
	EXPECT_EQ(w, FrameQueue::Wait::Lost);
	EXPECT_EQ(st.code(), ErrorCode::CameraLost);
	EXPECT_EQ(allocations.load(), 0);
}

} // namespace
} // namespace ports
} // namespace calped
