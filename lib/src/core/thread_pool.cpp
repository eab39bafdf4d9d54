// SPDX-License-Identifier: BSD-2-Clause
#include "core/thread_pool.h"

#include <system_error>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CALPED_CPU_RELAX() _mm_pause()
#elif defined(__aarch64__) || defined(__arm__)
#define CALPED_CPU_RELAX() __asm__ __volatile__("yield")
#else
#define CALPED_CPU_RELAX() ((void)0)
#endif

namespace calped {

namespace {
// Workers spin this many times for the next section before parking: the sections of one
// frame follow each other within microseconds, parking and waking costs more.
constexpr int kSpinsBeforePark = 4000;
} // namespace

ThreadPool::~ThreadPool() { stop(); }

void ThreadPool::stop()
{
	{
		std::lock_guard<std::mutex> lock(mutex_);
		quit_ = true;
	}
	wake_.notify_all();
	for (std::thread &t : threads_)
		t.join();
	threads_.clear();
	size_ = 1;
}

Status ThreadPool::start(int threads)
{
	if (threads < 1 || threads > kMaxThreads)
		return Status::error(ErrorCode::InvalidArgument, "%d threads: the detector takes 1 to %d",
				     threads, kMaxThreads);
	stop();
	quit_ = false;
	try {
		threads_.reserve(size_t(threads - 1));
		for (int w = 1; w < threads; w++)
			threads_.emplace_back([this, w] { workerLoop(w); });
	} catch (const std::system_error &e) {
		stop();
		return Status::error(ErrorCode::OutOfMemory, "could not start %d worker threads: %s",
				     threads - 1, e.what());
	} catch (const std::bad_alloc &) {
		stop();
		return Status::error(ErrorCode::OutOfMemory, "worker threads");
	}
	size_ = threads;
	return Status::success();
}

void ThreadPool::work(int worker)
{
	for (int task = next_.fetch_add(1, std::memory_order_relaxed); task < count_;
	     task = next_.fetch_add(1, std::memory_order_relaxed))
		fn_(context_, task, worker);
}

void ThreadPool::workerLoop(int worker)
{
	uint64_t seen = 0;
	for (;;) {
		// A new section: spin a little, then park until run() or stop() wakes us.
		uint64_t g = generation_.load(std::memory_order_acquire);
		for (int spin = 0; g == seen && spin < kSpinsBeforePark; spin++) {
			CALPED_CPU_RELAX();
			g = generation_.load(std::memory_order_acquire);
		}
		if (g == seen) {
			std::unique_lock<std::mutex> lock(mutex_);
			wake_.wait(lock, [&] {
				return quit_ || generation_.load(std::memory_order_acquire) != seen;
			});
			if (quit_)
				return;
			g = generation_.load(std::memory_order_acquire);
		}
		seen = g;
		work(worker);
		if (finished_.fetch_add(1, std::memory_order_acq_rel) + 1 == size_ - 1) {
			// The last one out wakes run() if it parked.
			std::lock_guard<std::mutex> lock(mutex_);
			done_.notify_one();
		}
	}
}

void ThreadPool::run(int count, TaskFn fn, void *context)
{
	if (count <= 0)
		return;
	if (size_ == 1 || count == 1) {
		for (int task = 0; task < count; task++)
			fn(context, task, 0);
		return;
	}
	fn_ = fn;
	context_ = context;
	count_ = count;
	next_.store(0, std::memory_order_relaxed);
	finished_.store(0, std::memory_order_relaxed);
	{
		// Under the lock so that a worker about to park cannot miss the wake-up.
		std::lock_guard<std::mutex> lock(mutex_);
		generation_.fetch_add(1, std::memory_order_release);
	}
	wake_.notify_all();
	work(0);
	// The barrier: every worker has left work() (and so finished its last task). Spin
	// a little, then park: on a loaded machine a worker may be off its core for a while.
	const int workers = size_ - 1;
	for (int spin = 0; spin < kSpinsBeforePark; spin++) {
		if (finished_.load(std::memory_order_acquire) == workers)
			return;
		CALPED_CPU_RELAX();
	}
	std::unique_lock<std::mutex> lock(mutex_);
	done_.wait(lock, [&] { return finished_.load(std::memory_order_acquire) == workers; });
}

} // namespace calped
