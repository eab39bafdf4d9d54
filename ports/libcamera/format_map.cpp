// SPDX-License-Identifier: BSD-2-Clause
#include "format_map.h"

#include <string>

namespace calped {
namespace ports {

bool calpedFormatFor(const libcamera::PixelFormat &format, PixelFormat &out)
{
	return calpedFormatForFourcc(format.fourcc(), format.modifier(), out);
}

bool libcameraFormatFor(PixelFormat format, libcamera::PixelFormat &out)
{
	uint32_t code;
	if (!fourccForCalped(format, code))
		return false;
	out = libcamera::PixelFormat(code);
	return true;
}

YuvEncoding yuvEncodingFor(const std::optional<libcamera::ColorSpace> &colorSpace)
{
	using CS = libcamera::ColorSpace;
	if (!colorSpace)
		return YuvEncoding::Bt601Limited;
	bool full = colorSpace->range == CS::Range::Full;
	// BT.2020 has no calped reader; BT.709 is its nearest neighbour.
	bool bt709 = colorSpace->ycbcrEncoding == CS::YcbcrEncoding::Rec709 ||
		     colorSpace->ycbcrEncoding == CS::YcbcrEncoding::Rec2020;
	if (bt709)
		return full ? YuvEncoding::Bt709Full : YuvEncoding::Bt709Limited;
	return full ? YuvEncoding::Bt601Full : YuvEncoding::Bt601Limited;
}

Status frameView(const libcamera::PixelFormat &format, int64_t width, int64_t height,
		 unsigned int stride, const MappedPlane *planes, int planeCount,
		 YuvEncoding encoding, ImageView &out)
{
	const std::string name = format.toString();
	return layoutFrame(format.fourcc(), format.modifier(), name.c_str(), width, height, stride,
			   planes, planeCount, encoding, out);
}

} // namespace ports
} // namespace calped
