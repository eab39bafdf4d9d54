// SPDX-License-Identifier: BSD-2-Clause
#include "frame_layout.h"

#include <climits>

namespace calped {
namespace ports {

namespace {

struct FormatPair {
	uint32_t fourcc;
	PixelFormat calped;
};

const FormatPair kFormats[] = {
	{ kFourccNV12, PixelFormat::NV12 },         { kFourccYUV420, PixelFormat::YUV420 },
	{ kFourccYUYV, PixelFormat::YUYV },         { kFourccRGB888, PixelFormat::BGR8 },
	{ kFourccBGR888, PixelFormat::RGB8 },       { kFourccR8, PixelFormat::Gray8 },
	{ kFourccSRGGB8, PixelFormat::BayerRGGB8 }, { kFourccSGRBG8, PixelFormat::BayerGRBG8 },
	{ kFourccSGBRG8, PixelFormat::BayerGBRG8 }, { kFourccSBGGR8, PixelFormat::BayerBGGR8 },
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
	const int64_t needed = stride * (rows - 1) + rowBytes;
	if (!plane.data || static_cast<int64_t>(plane.length) < needed)
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
	if (!plane.data || offset > static_cast<int64_t>(plane.length))
		return t;
	t.data = plane.data + offset;
	t.length = plane.length - static_cast<size_t>(offset);
	return t;
}

} // namespace

bool calpedFormatForFourcc(uint32_t fourcc, uint64_t modifier, PixelFormat &out)
{
	if (modifier != 0) // tiled or compressed layouts: not rows of samples
		return false;
	for (const FormatPair &f : kFormats) {
		if (f.fourcc == fourcc) {
			out = f.calped;
			return true;
		}
	}
	return false;
}

bool fourccForCalped(PixelFormat format, uint32_t &out)
{
	for (const FormatPair &f : kFormats) {
		if (f.calped == format) {
			out = f.fourcc;
			return true;
		}
	}
	return false;
}

Status layoutFrame(uint32_t fourcc, uint64_t modifier, const char *name, int64_t width,
		   int64_t height, uint64_t stride, const MappedPlane *planes, int planeCount,
		   YuvEncoding encoding, ImageView &out)
{
	PixelFormat calped;
	if (!calpedFormatForFourcc(fourcc, modifier, calped))
		return Status::error(ErrorCode::UnsupportedPixelFormat,
				     "libcamera format %s has no calped reader", name);
	if (width < 1 || height < 1 || width > kMaxFrameSide || height > kMaxFrameSide)
		return Status::error(ErrorCode::CameraError, "%s frame size %lldx%lld: sides must be 1..%d",
				     name, static_cast<long long>(width), static_cast<long long>(height),
				     kMaxFrameSide);
	if (stride > INT_MAX / 2)
		return Status::error(ErrorCode::CameraError, "%s stride %llu is too large", name,
				     static_cast<unsigned long long>(stride));
	if (planeCount < 1 || !planes)
		return Status::error(ErrorCode::CameraError, "%s buffer has no planes", name);

	const int w = static_cast<int>(width), h = static_cast<int>(height);
	const int64_t s = static_cast<int64_t>(stride);
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
		out = ImageView::nv12(planes[0].data, static_cast<int>(s), uv.data, static_cast<int>(s),
				      w, h, encoding);
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
		out = ImageView::yuv420(planes[0].data, static_cast<int>(s), u.data, static_cast<int>(cs),
					v.data, static_cast<int>(cs), w, h, encoding);
		return Status::success();
	}

	// One-plane formats.
	if (planeCount != 1)
		return Status::error(ErrorCode::CameraError, "%s buffer has %d planes", name,
				     planeCount);
	const int64_t rowBytes = ImageView::packedRowBytes(calped, w);
	if (!(st = checkPlane(name, 0, planes[0], s, rowBytes, height)).ok())
		return st;
	out = ImageView::packed(calped, planes[0].data, w, h, static_cast<int>(s));
	out.yuv = encoding;
	return Status::success();
}

} // namespace ports
} // namespace calped
