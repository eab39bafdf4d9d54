// SPDX-License-Identifier: BSD-2-Clause
#include <calped/image.h>

namespace calped {

const char *pixelFormatName(PixelFormat format)
{
	switch (format) {
	case PixelFormat::RGB8: return "RGB8";
	case PixelFormat::BGR8: return "BGR8";
	case PixelFormat::Gray8: return "Gray8";
	case PixelFormat::NV12: return "NV12";
	case PixelFormat::YUV420: return "YUV420";
	case PixelFormat::YUYV: return "YUYV";
	case PixelFormat::BayerRGGB8: return "BayerRGGB8";
	case PixelFormat::BayerGRBG8: return "BayerGRBG8";
	case PixelFormat::BayerGBRG8: return "BayerGBRG8";
	case PixelFormat::BayerBGGR8: return "BayerBGGR8";
	}
	return "unknown";
}

} // namespace calped
