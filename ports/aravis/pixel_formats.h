// SPDX-License-Identifier: BSD-2-Clause
// GenICam (PFNC) pixel formats a camera sends -> calped pixel formats lent without a copy,
// and the checks of what the camera says about its images. Pure functions of the camera's
// answers (no Aravis), so they are built everywhere and fuzzed (tests/fuzz/fuzz_aravis.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include <calped/image.h>
#include <calped/status.h>

namespace calped {
namespace ports {

// PFNC codes, as Aravis's ARV_PIXEL_FORMAT_* (GigE Vision 2.0 / GenICam PFNC).
constexpr uint32_t kPfncMono8 = 0x01080001u;
constexpr uint32_t kPfncRGB8 = 0x02180014u;      // "RGB8Packed"
constexpr uint32_t kPfncBGR8 = 0x02180015u;      // "BGR8Packed"
constexpr uint32_t kPfncYUV422Packed = 0x0210001fu; // U Y V Y: not YUYV, refused
constexpr uint32_t kPfncYUYV = 0x02100032u;      // "YUV422_YUYV_Packed"
constexpr uint32_t kPfncBayerGR8 = 0x01080008u;
constexpr uint32_t kPfncBayerRG8 = 0x01080009u;
constexpr uint32_t kPfncBayerGB8 = 0x0108000au;
constexpr uint32_t kPfncBayerBG8 = 0x0108000bu;

// The largest image side taken from a camera (sizes are network data: a larger one is a
// corrupt leader or register, and it keeps every row and stride within int).
constexpr int kMaxCameraSide = 16384;
// Row padding (GigE Vision's padding_x) beyond this is not a camera's.
constexpr int kMaxRowPadding = 65536;
// The payload may exceed the image (row padding, chunk data) by the image's size plus this.
constexpr size_t kPayloadSlackBytes = size_t(1) << 20;

// The calped format for a PFNC code; false when calped cannot take it without conversion.
bool pixelFormatFromPfnc(uint32_t pfnc, PixelFormat &out);

// A view on one received image: `padX` bytes of padding end each row (GigE Vision's
// padding_x). False when the format is planar, a side is outside 1..kMaxCameraSide, the
// padding outside 0..kMaxRowPadding, or `size` bytes cannot hold width x height in that
// layout.
bool viewReceivedImage(PixelFormat format, const uint8_t *data, size_t size, int width,
		       int height, int padX, ImageView &out);

// What the camera announces before acquisition (its PixelFormat, region and PayloadSize
// registers), checked before any buffer is allocated.
struct AnnouncedStream {
	uint32_t pfnc = 0;
	int64_t width = 0;
	int64_t height = 0;
	int64_t payload = 0; // bytes per buffer
};

struct StreamPlan {
	PixelFormat format = PixelFormat::Gray8;
	int width = 0;
	int height = 0;
	size_t payload = 0; // bytes to allocate per buffer
};

// The stream to allocate for, or CameraError naming the inconsistent answer: a pixel
// format calped does not read without conversion (`formatName`, the camera's name for it,
// is quoted), a side outside 1..kMaxCameraSide, a payload smaller than one image or larger
// than twice the image plus kPayloadSlackBytes.
Status planStream(const AnnouncedStream &announced, const char *formatName, StreamPlan &out);

} // namespace ports
} // namespace calped
