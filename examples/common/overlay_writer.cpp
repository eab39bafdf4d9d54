// SPDX-License-Identifier: BSD-2-Clause
#include "overlay_writer.h"

#include <cinttypes>
#include <cstdio>

#include "file_io.h"
#include "overlay.h"
#include "writers.h"

namespace calped {
namespace live {

bool OverlayWriter::open(const std::string &dir, std::string &error)
{
	dir_ = dir;
	return apps::makeDirectories(dir, error);
}

bool OverlayWriter::write(const ports::Frame &frame, const Detections &detections,
			  std::string &error)
{
	const ImageView &im = frame.image;
	if (im.format != PixelFormat::RGB8 && im.format != PixelFormat::BGR8 &&
	    im.format != PixelFormat::Gray8) {
		error = std::string("overlays are drawn on RGB8, BGR8 and Gray8 frames, not ") +
			pixelFormatName(im.format);
		return false;
	}
	const size_t bytes = static_cast<size_t>(im.width) * im.height * 3;
	if (canvas_.pixels.size() < bytes)
		canvas_.pixels.resize(bytes); // grows once, to the frame size
	canvas_.width = im.width;
	canvas_.height = im.height;
	for (int y = 0; y < im.height; y++) {
		const uint8_t *src = im.planes[0] + static_cast<size_t>(y) * im.strides[0];
		uint8_t *dst = canvas_.pixels.data() + static_cast<size_t>(y) * im.width * 3;
		for (int x = 0; x < im.width; x++) {
			if (im.format == PixelFormat::Gray8) {
				dst[3 * x] = dst[3 * x + 1] = dst[3 * x + 2] = src[x];
			} else {
				const bool bgr = im.format == PixelFormat::BGR8;
				dst[3 * x + 0] = src[3 * x + (bgr ? 2 : 0)];
				dst[3 * x + 1] = src[3 * x + 1];
				dst[3 * x + 2] = src[3 * x + (bgr ? 0 : 2)];
			}
		}
	}
	static const uint8_t kGreen[3] = { 0, 255, 0 };
	for (const Detection &d : detections)
		apps::drawRectangle(canvas_, d.x, d.y, d.w, d.h, 2, kGreen);
	return ports::writePng(dir_ + "/" + apps::overlayFileName(static_cast<long long>(frame.id)),
			       canvas_, error);
}

} // namespace live
} // namespace calped
