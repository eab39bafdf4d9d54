// SPDX-License-Identifier: BSD-2-Clause
#include "pixel_formats.h"

namespace calped {
namespace ports {

bool pixelFormatFromPfnc(uint32_t pfnc, PixelFormat &out)
{
	switch (pfnc) {
	case kPfncMono8: out = PixelFormat::Gray8; return true;
	case kPfncRGB8: out = PixelFormat::RGB8; return true;
	case kPfncBGR8: out = PixelFormat::BGR8; return true;
	case kPfncYUYV: out = PixelFormat::YUYV; return true;
	case kPfncBayerRG8: out = PixelFormat::BayerRGGB8; return true;
	case kPfncBayerGR8: out = PixelFormat::BayerGRBG8; return true;
	case kPfncBayerGB8: out = PixelFormat::BayerGBRG8; return true;
	case kPfncBayerBG8: out = PixelFormat::BayerBGGR8; return true;
	default: return false;
	}
}

bool viewReceivedImage(PixelFormat format, const uint8_t *data, size_t size, int width,
		       int height, int padX, ImageView &out)
{
	const int rowBytes = ImageView::packedRowBytes(format, width);
	if (!data || width <= 0 || height <= 0 || padX < 0 || rowBytes <= 0)
		return false;
	const size_t stride = static_cast<size_t>(rowBytes) + static_cast<size_t>(padX);
	// The last row needs no padding after it.
	if (stride * (static_cast<size_t>(height) - 1) + static_cast<size_t>(rowBytes) > size)
		return false;
	out = ImageView::packed(format, data, width, height, static_cast<int>(stride));
	return true;
}

} // namespace ports
} // namespace calped
