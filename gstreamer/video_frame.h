// SPDX-License-Identifier: BSD-2-Clause
// GStreamer video frames as calped images: caps formats to PixelFormat, the mapped planes
// and strides borrowed into an ImageView (no copy), and boxes drawn into a frame.
#pragma once

#include <gst/video/video.h>

#include <calped/detector.h>
#include <calped/image.h>

namespace calped::gst {

// The caps formats the element takes (its pad templates), as a caps format list.
#define CALPED_GST_FORMATS "{ NV12, I420, YUY2, RGB, BGR, GRAY8 }"

// calped's format for a GStreamer video format; false for any other.
bool pixelFormatFor(GstVideoFormat format, PixelFormat &out);

// How calped decodes the colour of YUV frames with this colorimetry: BT.709 for a BT.709
// matrix, BT.601 for every other (BT.601 is what cameras and the caps default give),
// full range when the caps say so.
YuvEncoding yuvEncodingFor(const GstVideoColorimetry &colorimetry);

// The mapped frame's planes and strides, borrowed.
ImageView imageViewOf(const GstVideoFrame &frame, PixelFormat format, YuvEncoding yuv);

// A detection's box in whole pixels of a width x height frame: each edge rounded to the
// nearest pixel, then clipped to the frame (boxes may reach past the border).
struct PixelBox {
	unsigned x = 0, y = 0, w = 0, h = 0;
};
PixelBox pixelBoxOf(const Detection &d, int width, int height);

// Draws the box's outline, 2 pixels wide, into a frame mapped for writing: green in RGB and
// BGR, white in GRAY8 and in the luma of the YUV formats (chroma is left alone).
void drawBox(GstVideoFrame &frame, const PixelBox &box);

} // namespace calped::gst
