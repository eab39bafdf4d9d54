// SPDX-License-Identifier: BSD-2-Clause
// Camera pixel formats -> interleaved RGB8, the reference (the specification of every
// conversion; docs/pixel-formats.md states the same formulas).
#include "kernels.h"

namespace calped {
namespace kernels {

namespace {

uint8_t clamp255(int32_t v) { return static_cast<uint8_t>(v < 0 ? 0 : (v > 255 ? 255 : v)); }

// One YUV sample to RGB with the Q8 coefficients (>> of a negative value floors).
void yuvPixel(const YuvCoeffs &c, int y, int u, int v, uint8_t *rgb)
{
	const int32_t luma = c.y * (y - c.yOffset) + 128;
	const int32_t d = u - 128, e = v - 128;
	rgb[0] = clamp255((luma + c.rv * e) >> 8);
	rgb[1] = clamp255((luma - c.gu * d - c.gv * e) >> 8);
	rgb[2] = clamp255((luma + c.bu * d) >> 8);
}

// Mirrored index: -1 -> 1, n -> n - 2 (keeps the Bayer parity; needs n >= 2).
int mirror(int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); }

} // namespace

YuvCoeffs yuvCoeffs(bool bt709, bool fullRange)
{
	// round(256 * coefficient); limited range stretches Y by 255/219, chroma by 255/224.
	if (bt709)
		return fullRange ? YuvCoeffs{ 256, 0, 403, 48, 120, 475 }
				 : YuvCoeffs{ 298, 16, 459, 55, 136, 541 };
	return fullRange ? YuvCoeffs{ 256, 0, 359, 88, 183, 454 }
			 : YuvCoeffs{ 298, 16, 409, 100, 208, 516 };
}

void bgr8ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		for (int x = 0; x < f.width; x++) {
			d[3 * x + 0] = s[3 * x + 2];
			d[3 * x + 1] = s[3 * x + 1];
			d[3 * x + 2] = s[3 * x + 0];
		}
	}
}

void gray8ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		for (int x = 0; x < f.width; x++)
			d[3 * x + 0] = d[3 * x + 1] = d[3 * x + 2] = s[x];
	}
}

void yuv420ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *luma = f.planes[0] + y * f.strides[0];
		const uint8_t *u = f.planes[1] + (y / 2) * f.strides[1];
		const uint8_t *v = f.planes[2] + (y / 2) * f.strides[2];
		uint8_t *d = dst + (y - y0) * dstStride;
		for (int x = 0; x < f.width; x++) {
			const int c = (x / 2) * f.chromaStep;
			yuvPixel(f.yuv, luma[x], u[c], v[c], d + 3 * x);
		}
	}
}

void yuyvToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++) {
		const uint8_t *s = f.planes[0] + y * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		for (int x = 0; x < f.width; x++) {
			const uint8_t *pair = s + 4 * (x / 2);
			yuvPixel(f.yuv, pair[2 * (x & 1)], pair[1], pair[3], d + 3 * x);
		}
	}
}

void bayerToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const int w = f.width, h = f.height;
	auto at = [&](int x, int y) -> int {
		return f.planes[0][mirror(y, h) * f.strides[0] + mirror(x, w)];
	};
	for (int y = y0; y < y0 + rows; y++) {
		uint8_t *d = dst + (y - y0) * dstStride;
		const bool redRow = (y & 1) == f.redY;
		for (int x = 0; x < w; x++) {
			const bool redColumn = (x & 1) == f.redX;
			const int here = at(x, y);
			const int cross = (at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1) + 2) >> 2;
			const int diagonal = (at(x - 1, y - 1) + at(x + 1, y - 1) + at(x - 1, y + 1) +
					      at(x + 1, y + 1) + 2) >> 2;
			const int across = (at(x - 1, y) + at(x + 1, y) + 1) >> 1;
			const int vertical = (at(x, y - 1) + at(x, y + 1) + 1) >> 1;
			int r, g, b;
			if (redRow && redColumn) { // red site
				r = here, g = cross, b = diagonal;
			} else if (!redRow && !redColumn) { // blue site
				r = diagonal, g = cross, b = here;
			} else if (redRow) { // green between reds (left, right) and blues (up, down)
				r = across, g = here, b = vertical;
			} else { // green between blues (left, right) and reds (up, down)
				r = vertical, g = here, b = across;
			}
			d[3 * x + 0] = uint8_t(r);
			d[3 * x + 1] = uint8_t(g);
			d[3 * x + 2] = uint8_t(b);
		}
	}
}

} // namespace kernels
} // namespace calped
