// SPDX-License-Identifier: BSD-2-Clause
#include "pixel_formats.h"

#include <algorithm>
#include <cmath>

namespace calped {
namespace test {

namespace {

uint8_t toByte(double v) { return uint8_t(std::clamp(std::lround(v), 0L, 255L)); }

struct Yuv {
	double y, u, v;
};

// RGB -> Y'CbCr with the encoding's matrix and range (the inverse of what cameras apply).
Yuv rgbToYuv(const uint8_t *p, YuvEncoding e)
{
	const bool bt709 = e == YuvEncoding::Bt709Limited || e == YuvEncoding::Bt709Full;
	const bool full = e == YuvEncoding::Bt601Full || e == YuvEncoding::Bt709Full;
	const double kr = bt709 ? 0.2126 : 0.299, kb = bt709 ? 0.0722 : 0.114;
	const double y = kr * p[0] + (1 - kr - kb) * p[1] + kb * p[2];
	const double cb = (p[2] - y) / (2 * (1 - kb)), cr = (p[0] - y) / (2 * (1 - kr));
	if (full)
		return { y, 128 + cb, 128 + cr };
	return { 16 + y * 219 / 255, 128 + cb * 224 / 255, 128 + cr * 224 / 255 };
}

// Mean chroma of the pixels (x, y) with x in [x0, x0 + nx), y in [y0, y0 + ny) that exist.
Yuv meanChroma(const uint8_t *rgb, int width, int height, int x0, int y0, int nx, int ny,
	       YuvEncoding e)
{
	Yuv sum = { 0, 0, 0 };
	int n = 0;
	for (int y = y0; y < std::min(y0 + ny, height); y++)
		for (int x = x0; x < std::min(x0 + nx, width); x++) {
			const Yuv c = rgbToYuv(rgb + 3 * (size_t(y) * width + x), e);
			sum.u += c.u;
			sum.v += c.v;
			n++;
		}
	return { 0, sum.u / n, sum.v / n };
}

} // namespace

ImageView FormattedImage::view() const
{
	ImageView v;
	for (int i = 0; i < 3; i++) {
		v.planes[i] = planes[i].empty() ? nullptr : planes[i].data();
		v.strides[i] = strides[i];
	}
	v.width = width;
	v.height = height;
	v.format = format;
	v.yuv = yuv;
	return v;
}

FormattedImage encodeImage(const uint8_t *rgb, int width, int height, PixelFormat format,
			   YuvEncoding yuv, int pad)
{
	FormattedImage out;
	out.width = width;
	out.height = height;
	out.format = format;
	out.yuv = yuv;
	const int cw = (width + 1) / 2, ch = (height + 1) / 2;
	auto plane = [&](int i, int rowBytes, int rows) {
		out.strides[i] = rowBytes + pad;
		out.planes[i].assign(size_t(out.strides[i]) * rows, 0xA5);
		return out.planes[i].data();
	};
	auto px = [&](int x, int y) { return rgb + 3 * (size_t(y) * width + x); };
	switch (format) {
	case PixelFormat::RGB8:
	case PixelFormat::BGR8: {
		uint8_t *d = plane(0, 3 * width, height);
		const bool swap = format == PixelFormat::BGR8;
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++)
				for (int c = 0; c < 3; c++)
					d[size_t(y) * out.strides[0] + 3 * x + c] = px(x, y)[swap ? 2 - c : c];
		break;
	}
	case PixelFormat::Gray8: {
		uint8_t *d = plane(0, width, height);
		const auto grey = greyRgb(rgb, width, height);
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++)
				d[size_t(y) * out.strides[0] + x] = grey[3 * (size_t(y) * width + x)];
		break;
	}
	case PixelFormat::NV12:
	case PixelFormat::YUV420: {
		uint8_t *luma = plane(0, width, height);
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++)
				luma[size_t(y) * out.strides[0] + x] = toByte(rgbToYuv(px(x, y), yuv).y);
		const bool nv12 = format == PixelFormat::NV12;
		uint8_t *u = plane(1, nv12 ? 2 * cw : cw, ch);
		uint8_t *v = nv12 ? u + 1 : plane(2, cw, ch);
		const int step = nv12 ? 2 : 1, vStride = out.strides[nv12 ? 1 : 2];
		for (int y = 0; y < ch; y++)
			for (int x = 0; x < cw; x++) {
				const Yuv c = meanChroma(rgb, width, height, 2 * x, 2 * y, 2, 2, yuv);
				u[size_t(y) * out.strides[1] + x * step] = toByte(c.u);
				v[size_t(y) * vStride + x * step] = toByte(c.v);
			}
		break;
	}
	case PixelFormat::YUYV: {
		uint8_t *d = plane(0, 4 * cw, height);
		for (int y = 0; y < height; y++)
			for (int x = 0; x < cw; x++) {
				uint8_t *q = d + size_t(y) * out.strides[0] + 4 * x;
				const Yuv c = meanChroma(rgb, width, height, 2 * x, y, 2, 1, yuv);
				q[0] = toByte(rgbToYuv(px(2 * x, y), yuv).y);
				q[1] = toByte(c.u);
				q[2] = 2 * x + 1 < width ? toByte(rgbToYuv(px(2 * x + 1, y), yuv).y) : 0;
				q[3] = toByte(c.v);
			}
		break;
	}
	default: { // Bayer: keep the channel the mosaic samples at each pixel
		uint8_t *d = plane(0, width, height);
		const int redX = format == PixelFormat::BayerGRBG8 || format == PixelFormat::BayerBGGR8;
		const int redY = format == PixelFormat::BayerGBRG8 || format == PixelFormat::BayerBGGR8;
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++) {
				const bool redRow = (y & 1) == redY, redColumn = (x & 1) == redX;
				const int c = redRow && redColumn ? 0 : (!redRow && !redColumn ? 2 : 1);
				d[size_t(y) * out.strides[0] + x] = px(x, y)[c];
			}
		break;
	}
	}
	return out;
}

std::vector<uint8_t> greyRgb(const uint8_t *rgb, int width, int height)
{
	std::vector<uint8_t> out(size_t(width) * height * 3);
	for (size_t i = 0; i < size_t(width) * height; i++) {
		const uint8_t *p = rgb + 3 * i;
		const uint8_t g = toByte(0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]);
		out[3 * i] = out[3 * i + 1] = out[3 * i + 2] = g;
	}
	return out;
}

} // namespace test
} // namespace calped
