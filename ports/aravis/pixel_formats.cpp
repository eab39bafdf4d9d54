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
	// Sides first: packedRowBytes is int arithmetic (3 x width overflows past INT_MAX / 3).
	if (!data || width <= 0 || height <= 0 || width > kMaxCameraSide ||
	    height > kMaxCameraSide || padX < 0 || padX > kMaxRowPadding)
		return false;
	const int rowBytes = ImageView::packedRowBytes(format, width);
	if (rowBytes <= 0)
		return false;
	const size_t stride = static_cast<size_t>(rowBytes) + static_cast<size_t>(padX);
	// The last row needs no padding after it.
	if (stride * (static_cast<size_t>(height) - 1) + static_cast<size_t>(rowBytes) > size)
		return false;
	out = ImageView::packed(format, data, width, height, static_cast<int>(stride));
	return true;
}

namespace {

// The camera's name for its format (from its GenICam description: outside text) as at most
// 32 printable ASCII characters, anything else as '?', so a message stays one clean line.
void printableName(const char *name, char (&out)[40])
{
	size_t n = 0;
	for (; name && name[n] && n < 32; n++) {
		const unsigned char c = static_cast<unsigned char>(name[n]);
		out[n] = c >= 0x20 && c < 0x7f ? static_cast<char>(c) : '?';
	}
	if (name && name[n])
		for (int i = 0; i < 3; i++)
			out[n++] = '.';
	if (n == 0)
		out[n++] = '?';
	out[n] = '\0';
}

} // namespace

Status planStream(const AnnouncedStream &a, const char *formatName, StreamPlan &out)
{
	PixelFormat format;
	if (!pixelFormatFromPfnc(a.pfnc, format)) {
		char name[40];
		printableName(formatName, name);
		return Status::error(ErrorCode::CameraError,
				     "pixel format %s (0x%08x) is not one calped reads without "
				     "conversion; choose Mono8, RGB8, BGR8, YUV422_YUYV_Packed or Bayer*8",
				     name, static_cast<unsigned>(a.pfnc));
	}
	if (a.width < 1 || a.height < 1 || a.width > kMaxCameraSide || a.height > kMaxCameraSide)
		return Status::error(ErrorCode::CameraError,
				     "the camera's region is %lldx%lld, sides must be 1..%d",
				     static_cast<long long>(a.width), static_cast<long long>(a.height),
				     kMaxCameraSide);
	const int width = static_cast<int>(a.width), height = static_cast<int>(a.height);
	const int64_t image = int64_t(ImageView::packedRowBytes(format, width)) * height;
	const int64_t most = 2 * image + int64_t(kPayloadSlackBytes);
	if (a.payload < image || a.payload > most)
		return Status::error(ErrorCode::CameraError,
				     "the camera's payload of %lld bytes does not fit a %dx%d %s image of "
				     "%lld bytes (it must be %lld..%lld)",
				     static_cast<long long>(a.payload), width, height,
				     pixelFormatName(format), static_cast<long long>(image),
				     static_cast<long long>(image), static_cast<long long>(most));
	out.format = format;
	out.width = width;
	out.height = height;
	out.payload = static_cast<size_t>(a.payload);
	return Status::success();
}

} // namespace ports
} // namespace calped
