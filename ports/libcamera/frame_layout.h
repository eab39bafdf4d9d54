// SPDX-License-Identifier: BSD-2-Clause
// What a libcamera stream says about its frames -- pixel format (a DRM fourcc and
// modifier), size, stride, the planes of each buffer -- checked against one another before
// a frame reaches the detector. Pure functions without libcamera: built everywhere and
// fuzzed (tests/fuzz/fuzz_libcamera.cpp); format_map.h is the libcamera-typed front.
//
//   libcamera   fourcc   calped       memory
//   NV12        NV12     NV12         Y plane, then interleaved U,V at half width and height
//   YUV420      YU12     YUV420       Y, U, V planes; chroma stride = Y stride / 2
//   YUYV        YUYV     YUYV         packed 4:2:2
//   RGB888      RG24     BGR8         B,G,R bytes per pixel (DRM naming: little-endian RGB)
//   BGR888      BG24     RGB8         R,G,B bytes per pixel
//   R8          "R8  "   Gray8
//   SRGGB8 ...  RGGB ... BayerRGGB8 ... (raw sensor streams; SBGGR8 is BA81)
//
// A buffer comes with one plane per colour plane (what libcamera normally describes, even
// when they share one dmabuf) or, for NV12 and YUV420, a single plane holding the colour
// planes back to back; both are read. Any modifier other than 0 (linear) is refused.
#pragma once

#include <cstdint>

#include <calped/image.h>
#include <calped/status.h>

#include "plane_mapping.h"

namespace calped {
namespace ports {

constexpr uint32_t fourcc(char a, char b, char c, char d)
{
	return uint32_t(uint8_t(a)) | uint32_t(uint8_t(b)) << 8 | uint32_t(uint8_t(c)) << 16 |
	       uint32_t(uint8_t(d)) << 24;
}

constexpr uint32_t kFourccNV12 = fourcc('N', 'V', '1', '2');
constexpr uint32_t kFourccYUV420 = fourcc('Y', 'U', '1', '2');
constexpr uint32_t kFourccYUYV = fourcc('Y', 'U', 'Y', 'V');
constexpr uint32_t kFourccRGB888 = fourcc('R', 'G', '2', '4');
constexpr uint32_t kFourccBGR888 = fourcc('B', 'G', '2', '4');
constexpr uint32_t kFourccR8 = fourcc('R', '8', ' ', ' ');
constexpr uint32_t kFourccSRGGB8 = fourcc('R', 'G', 'G', 'B');
constexpr uint32_t kFourccSGRBG8 = fourcc('G', 'R', 'B', 'G');
constexpr uint32_t kFourccSGBRG8 = fourcc('G', 'B', 'R', 'G');
constexpr uint32_t kFourccSBGGR8 = fourcc('B', 'A', '8', '1');

// The largest frame side taken from a stream configuration (it keeps rows within int).
constexpr int kMaxFrameSide = 16384;

// The calped format a fourcc (with its modifier) is read as; false when calped has none.
bool calpedFormatForFourcc(uint32_t fourcc, uint64_t modifier, PixelFormat &out);

// The fourcc that delivers a calped format (modifier 0); false when there is none.
bool fourccForCalped(PixelFormat format, uint32_t &out);

// Describes one frame of a stream (format, size, stride of the first plane as in
// StreamConfiguration::stride) held in mapped planes; `name` names the format in messages
// (the caller's printable name). Errors: UnsupportedPixelFormat for a format calped does
// not read; CameraError when a side is outside 1..kMaxFrameSide, the stride is shorter
// than a row, the plane count does not fit the format, or a plane is too short for its
// rows (the message names the plane and both sizes). On success every row of every plane
// of `out` lies inside the given planes.
Status layoutFrame(uint32_t fourcc, uint64_t modifier, const char *name, int64_t width,
		   int64_t height, uint64_t stride, const MappedPlane *planes, int planeCount,
		   YuvEncoding encoding, ImageView &out);

} // namespace ports
} // namespace calped
