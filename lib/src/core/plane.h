// SPDX-License-Identifier: BSD-2-Clause
// A 2-D array of samples: non-owning view (Plane) and an owning buffer (PlaneBuffer)
// whose capacity is fixed at setup, so views of any smaller size never reallocate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace calped {

template <typename T>
struct Plane {
	T *data = nullptr;
	int width = 0;
	int height = 0;
	ptrdiff_t stride = 0; // in elements

	T *row(int y) const { return data + y * stride; }
};

template <typename T>
class PlaneBuffer
{
public:
	static_assert(std::is_trivial<T>::value, "planes hold plain samples");

	// Reserve room for planes up to maxWidth x maxHeight (with extra slack elements),
	// zeroed. calloc: large buffers come from the system as untouched zero pages, so
	// memory is only resident where a frame actually writes (per-thread scratch sized for
	// the largest level but used in rectangles costs little). Throws std::bad_alloc.
	void allocate(int maxWidth, int maxHeight, size_t slack = 0)
	{
		storage_.reset();
		capacity_ = 0;
		const size_t n = size_t(maxWidth) * size_t(maxHeight) + slack;
		T *p = static_cast<T *>(std::calloc(n > 0 ? n : 1, sizeof(T)));
		if (!p)
			throw std::bad_alloc();
		storage_.reset(p);
		capacity_ = n;
	}
	size_t capacity() const { return capacity_; }
	// A view of width x height packed rows; the caller checked the size fits.
	Plane<T> view(int width, int height)
	{
		Plane<T> p;
		p.data = storage_.get();
		p.width = width;
		p.height = height;
		p.stride = width;
		return p;
	}
	bool fits(int width, int height) const
	{
		return size_t(width) * size_t(height) <= capacity_;
	}
	T *data() { return storage_.get(); }

private:
	struct Free {
		void operator()(T *p) const { std::free(p); }
	};
	std::unique_ptr<T[], Free> storage_;
	size_t capacity_ = 0;
};

} // namespace calped
