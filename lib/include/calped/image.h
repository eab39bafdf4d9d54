// SPDX-License-Identifier: BSD-2-Clause
// A non-owning view of one image in memory.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {

enum class PixelFormat {
	RGB8,   // interleaved R G B, one plane
	Gray8,  // reserved for the camera ports
	NV12,   // reserved: Y plane + interleaved UV plane
	YUV420, // reserved: Y, U, V planes
	YUYV,   // reserved: packed 4:2:2
};

// Borrowed pixels: the caller keeps the memory alive and unchanged while a function
// that received the view runs. Strides are in bytes and may exceed the row width.
struct ImageView {
	const uint8_t *planes[3] = { nullptr, nullptr, nullptr };
	int strides[3] = { 0, 0, 0 };
	int width = 0;
	int height = 0;
	PixelFormat format = PixelFormat::RGB8;

	// Interleaved RGB8 image; stride 0 means tightly packed (3 * width).
	static ImageView rgb8(const uint8_t *data, int width, int height, int stride = 0)
	{
		ImageView v;
		v.planes[0] = data;
		v.strides[0] = stride ? stride : 3 * width;
		v.width = width;
		v.height = height;
		v.format = PixelFormat::RGB8;
		return v;
	}
};

} // namespace calped
