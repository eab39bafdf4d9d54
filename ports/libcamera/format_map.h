// SPDX-License-Identifier: BSD-2-Clause
// libcamera pixel formats and buffer layouts as calped ImageViews: the libcamera-typed
// front of frame_layout.h (which has the table of formats and the checks).
#pragma once

#include <optional>

#include <libcamera/color_space.h>
#include <libcamera/pixel_format.h>

#include <calped/image.h>
#include <calped/status.h>

#include "frame_layout.h"
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
// StreamConfiguration::stride) held in mapped planes: layoutFrame() with the format's
// name. The size is taken as libcamera gives it (unsigned), so a huge one is refused, not
// wrapped.
Status frameView(const libcamera::PixelFormat &format, int64_t width, int64_t height,
		 unsigned int stride, const MappedPlane *planes, int planeCount,
		 YuvEncoding encoding, ImageView &out);

} // namespace ports
} // namespace calped
