// SPDX-License-Identifier: BSD-2-Clause
// libcamera pixel formats and buffer layouts as calped ImageViews.
//
//   libcamera   calped       memory
//   NV12        NV12         Y plane, then interleaved U,V at half width and height
//   YUV420      YUV420       Y, U, V planes; chroma stride = Y stride / 2
//   YUYV        YUYV         packed 4:2:2
//   RGB888      BGR8         B,G,R bytes per pixel (DRM fourcc naming: little-endian RGB)
//   BGR888      RGB8         R,G,B bytes per pixel
//   R8          Gray8
//   SRGGB8 ...  BayerRGGB8 ... (raw sensor streams)
//
// A buffer comes with one plane per colour plane (what libcamera normally describes, even
// when they share one dmabuf) or, for NV12 and YUV420, a single plane holding the colour
// planes back to back; both are read.
#pragma once

#include <optional>

#include <libcamera/color_space.h>
#include <libcamera/pixel_format.h>

#include <calped/image.h>
#include <calped/status.h>

#include "plane_mapping.h"

namespace calped {
namespace ports {

// The calped format a libcamera format is read as; false when calped has no reader for it.
bool calpedFormatFor(const libcamera::PixelFormat &format, PixelFormat &out);

// The libcamera format that delivers a calped format; false when there is none.
bool libcameraFormatFor(PixelFormat format, libcamera::PixelFormat &out);

// How a stream's YUV samples encode colour. No colour space, or one without a Y'CbCr
// encoding, reads as BT.601 limited range (what cameras mostly send).
YuvEncoding yuvEncodingFor(const std::optional<libcamera::ColorSpace> &colorSpace);

// Describes one frame of a stream (format, size, stride of the first plane as in
// StreamConfiguration::stride) held in mapped planes. Errors: UnsupportedPixelFormat for a
// format calped does not read; CameraError when the stride is shorter than a row, the
// plane count does not fit the format, or a plane is too short for its rows (the message
// names the plane and both sizes).
Status frameView(const libcamera::PixelFormat &format, int width, int height,
		 unsigned int stride, const MappedPlane *planes, int planeCount,
		 YuvEncoding encoding, ImageView &out);

} // namespace ports
} // namespace calped
