// SPDX-License-Identifier: BSD-2-Clause
#include "format_map.h"

#include <climits>
#include <string>

#include <libcamera/formats.h>

namespace calped {
namespace ports {

namespace {

struct FormatPair {
	libcamera::PixelFormat libcamera;
	PixelFormat calped;
};

const FormatPair kFormats[] = {
	{ libcamera::formats::NV12, PixelFormat::NV12 },
	{ libcamera::formats::YUV420, PixelFormat::YUV420 },
	{ libcamera::formats::YUYV, PixelFormat::YUYV },
	{ libcamera::formats::RGB888, PixelFormat::BGR8 },
	{ libcamera::formats::BGR888, PixelFormat::RGB8 },
	{ libcamera::formats::R8, PixelFormat::Gray8 },
	{ libcamera::formats::SRGGB8, PixelFormat::BayerRGGB8 },
	{ libcamera::formats::SGRBG8, PixelFormat::BayerGRBG8 },
	{ libcamera::formats::SGBRG8, PixelFormat::BayerGBRG8 },
	{ libcamera::formats::SBGGR8, PixelFormat::BayerBGGR8 },
};

// Checks that a plane holds `rows` rows of `rowBytes` bytes `stride` apart.
Status checkPlane(const char *format, int index, const MappedPlane &plane, int64_t stride,
		  int64_t rowBytes, int64_t rows)
{
	if (stride < rowBytes)
		return Status::error(ErrorCode::CameraError,
				     "%s plane %d: stride %lld is shorter than a row of %lld bytes",
				     format, index, static_cast<long long>(stride),
				     static_cast<long long>(rowBytes));
	int64_t needed = stride * (rows - 1) + rowBytes;
	if (static_cast<int64_t>(plane.length) < needed)
		return Status::error(ErrorCode::CameraError,
				     "%s plane %d is %zu bytes, %lld rows of stride %lld need %lld",
				     format, index, plane.length, static_cast<long long>(rows),
				     static_cast<long long>(stride), static_cast<long long>(needed));
	return Status::success();
}

// The part of a plane after `offset` bytes (for colour planes stored back to back).
MappedPlane tail(const MappedPlane &plane, int64_t offset)
{
	MappedPlane t;
	if (offset > static_cast<int64_t>(plane.length))
		return t;
	t.data = plane.data + offset;
	t.length = plane.length - static_cast<size_t>(offset);
	return t;
}

} // namespace

bool calpedFormatFor(const libcamera::PixelFormat &format, PixelFormat &out)
{
	for (const FormatPair &f : kFormats) {
		if (f.libcamera == format) {
			out = f.calped;
			return true;
		}
	}
	return false;
}

bool libcameraFormatFor(PixelFormat format, libcamera::PixelFormat &out)
{
	for (const FormatPair &f : kFormats) {
		if (f.calped == format) {
			out = f.libcamera;
			return true;
		}
	}
	return false;
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

Status frameView(const libcamera::PixelFormat &format, int width, int height,
		 unsigned int stride, const MappedPlane *planes, int planeCount,
		 YuvEncoding encoding, ImageView &out)
{
	PixelFormat calped;
	std::string name = format.toString();
	if (!calpedFormatFor(format, calped))
		return Status::error(ErrorCode::UnsupportedPixelFormat,
				     "libcamera format %s has no calped reader", name.c_str());
	if (width <= 0 || height <= 0)
		return Status::error(ErrorCode::CameraError, "%s frame size %dx%d is empty",
				     name.c_str(), width, height);
	if (stride > INT_MAX / 2)
		return Status::error(ErrorCode::CameraError, "%s stride %u is too large",
				     name.c_str(), stride);
	if (planeCount < 1)
		return Status::error(ErrorCode::CameraError, "%s buffer has no planes", name.c_str());

	const int64_t s = stride;
	const int64_t chromaWidth = (width + 1) / 2;
	const int64_t chromaRows = (height + 1) / 2;
	Status st;

	if (calped == PixelFormat::NV12) {
		if (planeCount > 2)
			return Status::error(ErrorCode::CameraError, "NV12 buffer has %d planes",
					     planeCount);
		MappedPlane uv = planeCount == 2 ? planes[1] : tail(planes[0], s * height);
		if (!(st = checkPlane("NV12", 0, planes[0], s, width, height)).ok() ||
		    !(st = checkPlane("NV12", 1, uv, s, 2 * chromaWidth, chromaRows)).ok())
			return st;
		out = ImageView::nv12(planes[0].data, stride, uv.data, stride, width, height,
				      encoding);
		return Status::success();
	}

	if (calped == PixelFormat::YUV420) {
		if (planeCount != 1 && planeCount != 3)
			return Status::error(ErrorCode::CameraError, "YUV420 buffer has %d planes",
					     planeCount);
		const int64_t cs = s / 2;
		MappedPlane u = planeCount == 3 ? planes[1] : tail(planes[0], s * height);
		MappedPlane v = planeCount == 3 ? planes[2]
						: tail(planes[0], s * height + cs * chromaRows);
		if (!(st = checkPlane("YUV420", 0, planes[0], s, width, height)).ok() ||
		    !(st = checkPlane("YUV420", 1, u, cs, chromaWidth, chromaRows)).ok() ||
		    !(st = checkPlane("YUV420", 2, v, cs, chromaWidth, chromaRows)).ok())
			return st;
		out = ImageView::yuv420(planes[0].data, stride, u.data, static_cast<int>(cs), v.data,
					static_cast<int>(cs), width, height, encoding);
		return Status::success();
	}

	// One-plane formats.
	if (planeCount != 1)
		return Status::error(ErrorCode::CameraError, "%s buffer has %d planes", name.c_str(),
				     planeCount);
	int64_t rowBytes = ImageView::packedRowBytes(calped, width);
	if (!(st = checkPlane(name.c_str(), 0, planes[0], s, rowBytes, height)).ok())
		return st;
	out = ImageView::packed(calped, planes[0].data, width, height, static_cast<int>(stride));
	out.yuv = encoding;
	return Status::success();
}

} // namespace ports
} // namespace calped
