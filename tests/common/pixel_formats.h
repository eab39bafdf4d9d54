// SPDX-License-Identifier: BSD-2-Clause
// Test inputs in camera pixel formats, made from RGB8 images: YUV encoders (the inverse
// of the BT.601 / BT.709 matrices, chroma averaged over the pixels sharing a sample),
// Bayer mosaics, BGR and grey. Rows may be padded (stride > row) to test strides.
#pragma once

#include <calped/image.h>

#include <cstdint>
#include <vector>

namespace calped {
namespace test {

// Owns the planes an ImageView points to.
struct FormattedImage {
	std::vector<uint8_t> planes[3];
	int strides[3] = { 0, 0, 0 };
	int width = 0, height = 0;
	PixelFormat format = PixelFormat::RGB8;
	YuvEncoding yuv = YuvEncoding::Bt601Limited;
	ImageView view() const;
};

// `rgb` is width x height interleaved RGB, tightly packed. `pad` bytes follow every row
// of every plane (filled with 0xA5, so a reader that strays into them changes results).
FormattedImage encodeImage(const uint8_t *rgb, int width, int height, PixelFormat format,
			   YuvEncoding yuv = YuvEncoding::Bt601Limited, int pad = 0);

// A grey RGB image (R = G = B = round(0.299 R + 0.587 G + 0.114 B)) of the same size.
std::vector<uint8_t> greyRgb(const uint8_t *rgb, int width, int height);

} // namespace test
} // namespace calped
