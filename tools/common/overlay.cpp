// SPDX-License-Identifier: BSD-2-Clause
#include "overlay.h"

#include <algorithm>
#include <cmath>

namespace calped::apps {

namespace {

void fillRect(RgbImage &image, long x0, long y0, long x1, long y1, const uint8_t rgb[3])
{
	// Half-open [x0, x1) x [y0, y1), clipped.
	x0 = std::max(x0, 0L);
	y0 = std::max(y0, 0L);
	x1 = std::min(x1, static_cast<long>(image.width));
	y1 = std::min(y1, static_cast<long>(image.height));
	for (long y = y0; y < y1; y++) {
		uint8_t *row = image.pixels.data() + static_cast<size_t>(y) * image.width * 3;
		for (long x = x0; x < x1; x++) {
			row[3 * x + 0] = rgb[0];
			row[3 * x + 1] = rgb[1];
			row[3 * x + 2] = rgb[2];
		}
	}
}

// Clamp before converting so NaN or huge boxes cannot overflow the integer maths.
long toPixel(float v)
{
	if (!std::isfinite(v))
		return 0;
	double c = std::min(std::max(static_cast<double>(v), -1e7), 1e7);
	return std::lround(c);
}

} // namespace

void drawRectangle(RgbImage &image, float x, float y, float w, float h, int thickness,
		   const uint8_t rgb[3])
{
	long x0 = toPixel(x), y0 = toPixel(y);
	long x1 = toPixel(x + w), y1 = toPixel(y + h);
	if (x1 <= x0 || y1 <= y0)
		return;
	long t = thickness;
	fillRect(image, x0, y0, x1, std::min(y0 + t, y1), rgb);      // top
	fillRect(image, x0, std::max(y1 - t, y0), x1, y1, rgb);      // bottom
	fillRect(image, x0, y0, std::min(x0 + t, x1), y1, rgb);      // left
	fillRect(image, std::max(x1 - t, x0), y0, x1, y1, rgb);      // right
}

RgbImage renderOverlay(const RgbImage &frame, const Detections &detections)
{
	static const uint8_t kGreen[3] = { 0, 255, 0 };
	RgbImage out = frame;
	for (const Detection &d : detections)
		drawRectangle(out, d.x, d.y, d.w, d.h, 2, kGreen);
	return out;
}

} // namespace calped::apps
