// SPDX-License-Identifier: BSD-2-Clause
#include "video_frame.h"

#include <algorithm>
#include <cmath>

namespace calped::gst {

bool pixelFormatFor(GstVideoFormat format, PixelFormat &out)
{
	static const struct {
		GstVideoFormat gst;
		PixelFormat calped;
	} kFormats[] = {
		{ GST_VIDEO_FORMAT_NV12, PixelFormat::NV12 },  { GST_VIDEO_FORMAT_I420, PixelFormat::YUV420 },
		{ GST_VIDEO_FORMAT_YUY2, PixelFormat::YUYV },  { GST_VIDEO_FORMAT_RGB, PixelFormat::RGB8 },
		{ GST_VIDEO_FORMAT_BGR, PixelFormat::BGR8 },   { GST_VIDEO_FORMAT_GRAY8, PixelFormat::Gray8 },
	};
	for (const auto &f : kFormats) {
		if (f.gst == format) {
			out = f.calped;
			return true;
		}
	}
	return false;
}

YuvEncoding yuvEncodingFor(const GstVideoColorimetry &colorimetry)
{
	const bool full = colorimetry.range == GST_VIDEO_COLOR_RANGE_0_255;
	if (colorimetry.matrix == GST_VIDEO_COLOR_MATRIX_BT709)
		return full ? YuvEncoding::Bt709Full : YuvEncoding::Bt709Limited;
	return full ? YuvEncoding::Bt601Full : YuvEncoding::Bt601Limited;
}

ImageView imageViewOf(const GstVideoFrame &frame, PixelFormat format, YuvEncoding yuv)
{
	ImageView v;
	const guint planes = std::min<guint>(GST_VIDEO_FRAME_N_PLANES(&frame), 3);
	for (guint i = 0; i < planes; i++) {
		v.planes[i] = static_cast<const uint8_t *>(GST_VIDEO_FRAME_PLANE_DATA(&frame, i));
		v.strides[i] = GST_VIDEO_FRAME_PLANE_STRIDE(&frame, i);
	}
	v.width = GST_VIDEO_FRAME_WIDTH(&frame);
	v.height = GST_VIDEO_FRAME_HEIGHT(&frame);
	v.format = format;
	v.yuv = yuv;
	return v;
}

namespace {

// One edge rounded and clipped to 0..limit.
unsigned edge(double v, int limit)
{
	const long r = std::lround(v);
	return static_cast<unsigned>(std::clamp<long>(r, 0, limit));
}

// Where a box is drawn: plane 0, `step` bytes from one pixel to the next, `n` bytes of
// `value` written per pixel.
struct Pen {
	int step = 1, n = 1;
	uint8_t value[3] = { 255, 255, 255 };
};

Pen penFor(GstVideoFormat format)
{
	Pen p;
	switch (format) {
	case GST_VIDEO_FORMAT_RGB:
	case GST_VIDEO_FORMAT_BGR:
		p.step = 3;
		p.n = 3;
		p.value[0] = 0;
		p.value[2] = 0;
		break;
	case GST_VIDEO_FORMAT_YUY2:
		p.step = 2; // Y0 U Y1 V: the luma of pixel x is byte 2x
		break;
	default: // GRAY8, and the luma planes of NV12 and I420
		break;
	}
	return p;
}

void fill(GstVideoFrame &frame, const Pen &pen, unsigned x0, unsigned y0, unsigned x1, unsigned y1)
{
	uint8_t *base = static_cast<uint8_t *>(GST_VIDEO_FRAME_PLANE_DATA(&frame, 0));
	const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(&frame, 0);
	for (unsigned y = y0; y < y1; y++) {
		uint8_t *p = base + static_cast<ptrdiff_t>(y) * stride + static_cast<ptrdiff_t>(x0) * pen.step;
		for (unsigned x = x0; x < x1; x++, p += pen.step)
			std::copy(pen.value, pen.value + pen.n, p);
	}
}

} // namespace

PixelBox pixelBoxOf(const Detection &d, int width, int height)
{
	PixelBox b;
	b.x = edge(d.x, width);
	b.y = edge(d.y, height);
	b.w = edge(static_cast<double>(d.x) + d.w, width) - b.x;
	b.h = edge(static_cast<double>(d.y) + d.h, height) - b.y;
	return b;
}

void drawBox(GstVideoFrame &frame, const PixelBox &box)
{
	if (box.w == 0 || box.h == 0)
		return;
	const Pen pen = penFor(GST_VIDEO_FRAME_FORMAT(&frame));
	const unsigned t = 2;
	const unsigned x1 = box.x + box.w, y1 = box.y + box.h;
	const unsigned tx = std::min(t, box.w), ty = std::min(t, box.h);
	fill(frame, pen, box.x, box.y, x1, box.y + ty);      // top
	fill(frame, pen, box.x, y1 - ty, x1, y1);            // bottom
	fill(frame, pen, box.x, box.y, box.x + tx, y1);      // left
	fill(frame, pen, x1 - tx, box.y, x1, y1);            // right
}

} // namespace calped::gst
