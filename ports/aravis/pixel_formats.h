// SPDX-License-Identifier: BSD-2-Clause
// GenICam (PFNC) pixel formats a camera sends -> calped pixel formats lent without a copy.
#pragma once

#include <cstddef>
#include <cstdint>

#include <calped/image.h>

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

// The calped format for a PFNC code; false when calped cannot take it without conversion.
bool pixelFormatFromPfnc(uint32_t pfnc, PixelFormat &out);

// A view on one received image: `padX` bytes of padding end each row (GigE Vision's
// padding_x). False when `size` bytes cannot hold width x height in that layout.
bool viewReceivedImage(PixelFormat format, const uint8_t *data, size_t size, int width,
		       int height, int padX, ImageView &out);

} // namespace ports
} // namespace calped
