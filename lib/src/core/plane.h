// SPDX-License-Identifier: BSD-2-Clause
// A 2-D array of samples: non-owning view (Plane) and an owning buffer (PlaneBuffer)
// whose capacity is fixed at setup, so views of any smaller size never reallocate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

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
	// Reserve room for planes up to maxWidth x maxHeight (with extra slack elements).
	void allocate(int maxWidth, int maxHeight, size_t slack = 0)
	{
		capacity_ = size_t(maxWidth) * size_t(maxHeight) + slack;
		storage_.assign(capacity_, T());
	}
	size_t capacity() const { return capacity_; }
	// A view of width x height packed rows; the caller checked the size fits.
	Plane<T> view(int width, int height)
	{
		Plane<T> p;
		p.data = storage_.data();
		p.width = width;
		p.height = height;
		p.stride = width;
		return p;
	}
	bool fits(int width, int height) const
	{
		return size_t(width) * size_t(height) <= capacity_;
	}
	T *data() { return storage_.data(); }

private:
	std::vector<T> storage_;
	size_t capacity_ = 0;
};

} // namespace calped
