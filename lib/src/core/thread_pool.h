// SPDX-License-Identifier: BSD-2-Clause
// A fixed pool of worker threads for the detector's parallel sections. start() creates
// threads - 1 workers once (setup time); run() hands a section's tasks to them and to the
// calling thread, which takes part, and returns when every task is done (the one barrier
// of a section). Tasks are taken in index order from an atomic counter; which thread runs
// a task must not change its result: each task writes only its own outputs. run() neither
// allocates nor creates threads; its only lock is the hand-off (waking parked workers, and
// the caller parking at the barrier after a short spin).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include <calped/status.h>

namespace calped {

class ThreadPool
{
public:
	// fn(context, task, worker): worker is 0 for the calling thread, 1..size()-1 for the
	// pool's own threads (an index into per-thread scratch).
	using TaskFn = void (*)(void *context, int task, int worker);

	ThreadPool() = default;
	ThreadPool(const ThreadPool &) = delete;
	ThreadPool &operator=(const ThreadPool &) = delete;
	~ThreadPool();

	// threads >= 1 in all, the caller included; InvalidArgument beyond 1..kMaxThreads,
	// OutOfMemory when the system refuses a thread.
	Status start(int threads);
	static constexpr int kMaxThreads = 64;
	int size() const { return size_; }

	// Runs fn for tasks 0 .. count-1 over the pool and returns when all are done.
	void run(int count, TaskFn fn, void *context);
	// The same for a callable f(task, worker), called by reference (no copy, no allocation).
	template <class F>
	void forEach(int count, F &f)
	{
		run(count, [](void *c, int task, int worker) { (*static_cast<F *>(c))(task, worker); }, &f);
	}

private:
	void workerLoop(int worker);
	void work(int worker);
	void stop();

	int size_ = 1;
	std::vector<std::thread> threads_;
	// The section being run: set by run() before the generation moves on.
	TaskFn fn_ = nullptr;
	void *context_ = nullptr;
	int count_ = 0;
	std::atomic<int> next_{ 0 };     // next task to hand out
	std::atomic<int> finished_{ 0 }; // workers done with this section
	std::atomic<uint64_t> generation_{ 0 };
	bool quit_ = false;           // under mutex_
	std::mutex mutex_;
	std::condition_variable wake_; // workers: a new section or quit_
	std::condition_variable done_; // run(): the last worker finished the section
};

// f(task, worker) for tasks 0 .. count-1: on the pool, or on this thread without one.
template <class F>
void forEachTask(ThreadPool *pool, int count, F &f)
{
	if (pool)
		pool->forEach(count, f);
	else
		for (int task = 0; task < count; task++)
			f(task, 0);
}

} // namespace calped
