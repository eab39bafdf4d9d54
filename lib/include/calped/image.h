// SPDX-License-Identifier: BSD-2-Clause
// A non-owning view of one image in memory, in any of the pixel formats cameras deliver.
// docs/pixel-formats.md gives each format's layout and its exact conversion to RGB.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {

enum class PixelFormat {
	RGB8,       // interleaved R G B, one plane
	BGR8,       // interleaved B G R (libcamera's "RGB888", Aravis BGR8), one plane
	Gray8,      // one luminance plane; colour channels are those of a grey RGB image
	NV12,       // Y plane + interleaved U V plane at half width and height (4:2:0)
	YUV420,     // Y, U, V planes, chroma at half width and height (I420)
	YUYV,       // packed 4:2:2: Y0 U Y1 V for each pair of pixels, one plane
	BayerRGGB8, // raw 8-bit Bayer mosaics, named by their top-left 2x2 block
	BayerGRBG8,
	BayerGBRG8,
	BayerBGGR8,
};

// How YUV formats encode colour (ignored by the others). Cameras mostly send BT.601;
// "limited" is video range (Y 16..235, chroma 16..240), "full" is 0..255 (JPEG, sYCC).
enum class YuvEncoding { Bt601Limited, Bt601Full, Bt709Limited, Bt709Full };

// Borrowed pixels: the caller keeps the memory alive and unchanged while a function
// that received the view runs. Strides are in bytes and may exceed the row width.
// Chroma planes of odd-sized 4:2:0 images have ceil(width/2) x ceil(height/2) samples.
struct ImageView {
	const uint8_t *planes[3] = { nullptr, nullptr, nullptr };
	int strides[3] = { 0, 0, 0 };
	int width = 0;
	int height = 0;
	PixelFormat format = PixelFormat::RGB8;
	YuvEncoding yuv = YuvEncoding::Bt601Limited;

	// One-plane formats (RGB8, BGR8, Gray8, YUYV, Bayer); stride 0 means tightly packed.
	static ImageView packed(PixelFormat format, const uint8_t *data, int width, int height,
				int stride = 0)
	{
		ImageView v;
		v.planes[0] = data;
		v.strides[0] = stride ? stride : packedRowBytes(format, width);
		v.width = width;
		v.height = height;
		v.format = format;
		return v;
	}
	static ImageView rgb8(const uint8_t *data, int width, int height, int stride = 0)
	{
		return packed(PixelFormat::RGB8, data, width, height, stride);
	}
	static ImageView gray8(const uint8_t *data, int width, int height, int stride = 0)
	{
		return packed(PixelFormat::Gray8, data, width, height, stride);
	}
	static ImageView nv12(const uint8_t *y, int yStride, const uint8_t *uv, int uvStride,
			      int width, int height, YuvEncoding enc = YuvEncoding::Bt601Limited)
	{
		ImageView v;
		v.planes[0] = y;
		v.planes[1] = uv;
		v.strides[0] = yStride;
		v.strides[1] = uvStride;
		v.width = width;
		v.height = height;
		v.format = PixelFormat::NV12;
		v.yuv = enc;
		return v;
	}
	static ImageView yuv420(const uint8_t *y, int yStride, const uint8_t *u, int uStride,
				const uint8_t *v, int vStride, int width, int height,
				YuvEncoding enc = YuvEncoding::Bt601Limited)
	{
		ImageView i;
		i.planes[0] = y;
		i.planes[1] = u;
		i.planes[2] = v;
		i.strides[0] = yStride;
		i.strides[1] = uStride;
		i.strides[2] = vStride;
		i.width = width;
		i.height = height;
		i.format = PixelFormat::YUV420;
		i.yuv = enc;
		return i;
	}

	// Bytes of one tightly packed row of a one-plane format (0 for planar formats).
	static int packedRowBytes(PixelFormat format, int width)
	{
		switch (format) {
		case PixelFormat::RGB8:
		case PixelFormat::BGR8:
			return 3 * width;
		case PixelFormat::YUYV:
			return 2 * ((width + 1) / 2) * 2;
		case PixelFormat::Gray8:
		case PixelFormat::BayerRGGB8:
		case PixelFormat::BayerGRBG8:
		case PixelFormat::BayerGBRG8:
		case PixelFormat::BayerBGGR8:
			return width;
		default:
			return 0;
		}
	}
};

// Name of a pixel format, e.g. "NV12".
const char *pixelFormatName(PixelFormat format);

} // namespace calped
