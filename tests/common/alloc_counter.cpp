// SPDX-License-Identifier: BSD-2-Clause
#include "common/alloc_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

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
namespace test {

void startCountingAllocations()
{
	allocations = 0;
	counting = true;
}

long stopCountingAllocations()
{
	counting = false;
	return allocations.load();
}

} // namespace test
} // namespace calped
