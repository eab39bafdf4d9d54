// SPDX-License-Identifier: BSD-2-Clause
#include "input/frame_input.h"

#include <cstdint>
#include <new>

namespace calped {

namespace {

bool isBayer(PixelFormat f)
{
	return f == PixelFormat::BayerRGGB8 || f == PixelFormat::BayerGRBG8 ||
	       f == PixelFormat::BayerGBRG8 || f == PixelFormat::BayerBGGR8;
}

bool isYuv(PixelFormat f)
{
	return f == PixelFormat::NV12 || f == PixelFormat::YUV420 || f == PixelFormat::YUYV;
}

bool knownFormat(PixelFormat f)
{
	return f == PixelFormat::RGB8 || f == PixelFormat::BGR8 || f == PixelFormat::Gray8 ||
	       isYuv(f) || isBayer(f);
}

// A plane of `rows` rows of at least `rowBytes` bytes each, with the stride in plane i.
Status checkPlane(const ImageView &image, int i, const char *plane, int rowBytes, int rows)
{
	const char *name = pixelFormatName(image.format);
	if (!image.planes[i])
		return Status::error(ErrorCode::ImageEmpty, "%s image has no %s plane (planes[%d] is null)",
				     name, plane, i);
	if (image.strides[i] < rowBytes)
		return Status::error(ErrorCode::InvalidArgument,
				     "%s %s plane stride %d (strides[%d]) is smaller than its %d-byte rows "
				     "(width %d)",
				     name, plane, image.strides[i], i, rowBytes, image.width);
	if (double(image.strides[i]) * rows > double(PTRDIFF_MAX))
		return Status::error(ErrorCode::InvalidArgument,
				     "%s %s plane stride %d x %d rows exceeds the address space", name,
				     plane, image.strides[i], rows);
	return Status::success();
}

} // namespace

Status checkImageLayout(const ImageView &image)
{
	const PixelFormat f = image.format;
	if (!knownFormat(f))
		return Status::error(ErrorCode::UnsupportedPixelFormat,
				     "pixel format %d is not one calped knows (see docs/pixel-formats.md)",
				     int(f));
	const char *name = pixelFormatName(f);
	const int w = image.width, h = image.height;
	if (w <= 0 || h <= 0 || !image.planes[0])
		return Status::error(ErrorCode::ImageEmpty, "%s image is %dx%d with %s data", name, w, h,
				     image.planes[0] ? "some" : "no");
	if (isYuv(f)) {
		const int e = int(image.yuv);
		if (e < int(YuvEncoding::Bt601Limited) || e > int(YuvEncoding::Bt709Full))
			return Status::error(ErrorCode::InvalidArgument,
					     "%s image has an unknown YUV encoding %d", name, e);
	}
	// Chroma of 4:2:0 and 4:2:2 covers odd sizes: ceil(w/2) x ceil(h/2) samples.
	const int cw = (w + 1) / 2, ch = (h + 1) / 2;
	Status st;
	switch (f) {
	case PixelFormat::RGB8:
	case PixelFormat::BGR8:
		return checkPlane(image, 0, "pixel", 3 * w, h);
	case PixelFormat::Gray8:
		return checkPlane(image, 0, "pixel", w, h);
	case PixelFormat::YUYV:
		return checkPlane(image, 0, "pixel", 4 * cw, h);
	case PixelFormat::NV12:
		st = checkPlane(image, 0, "Y", w, h);
		return st.ok() ? checkPlane(image, 1, "UV", 2 * cw, ch) : st;
	case PixelFormat::YUV420:
		st = checkPlane(image, 0, "Y", w, h);
		if (st.ok())
			st = checkPlane(image, 1, "U", cw, ch);
		return st.ok() ? checkPlane(image, 2, "V", cw, ch) : st;
	default: // Bayer: bilinear demosaicing needs a neighbour on each axis.
		if (w < 2 || h < 2)
			return Status::error(ErrorCode::ImageTooSmall,
					     "%s image is %dx%d; Bayer mosaics need at least 2x2 pixels",
					     name, w, h);
		return checkPlane(image, 0, "pixel", w, h);
	}
}

Status FrameInput::init(int maxWidth, int maxHeight, bool wholeFrames,
			const kernels::ConvertKernels &k)
{
	k_ = &k;
	maxWidth_ = maxWidth;
	maxHeight_ = maxHeight;
	try {
		strip_.assign(size_t(kStripRows) * maxWidth * 3, 0);
		if (wholeFrames)
			whole_.assign(size_t(maxWidth) * maxHeight * 3, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory,
				     "input conversion buffers for %dx%d frames do not fit in memory",
				     maxWidth, maxHeight);
	}
	return Status::success();
}

kernels::ConvertRowsFn FrameInput::converter() const
{
	switch (image_.format) {
	case PixelFormat::BGR8: return k_->bgr8;
	case PixelFormat::Gray8: return k_->gray8;
	case PixelFormat::NV12:
	case PixelFormat::YUV420: return k_->yuv420;
	case PixelFormat::YUYV: return k_->yuyv;
	case PixelFormat::BayerRGGB8:
	case PixelFormat::BayerGRBG8:
	case PixelFormat::BayerGBRG8:
	case PixelFormat::BayerBGGR8: return k_->bayer;
	default: return nullptr; // RGB8 is used as it is
	}
}

void FrameInput::begin(const ImageView &image)
{
	image_ = image;
	raw_ = kernels::RawFrame();
	for (int i = 0; i < 3; i++) {
		raw_.planes[i] = image.planes[i];
		raw_.strides[i] = image.strides[i];
	}
	raw_.width = image.width;
	raw_.height = image.height;
	if (image.format == PixelFormat::NV12) { // V follows U in the interleaved plane
		raw_.planes[2] = image.planes[1] + 1;
		raw_.strides[2] = image.strides[1];
		raw_.chromaStep = 2;
	}
	const YuvEncoding e = image.yuv;
	raw_.yuv = kernels::yuvCoeffs(e == YuvEncoding::Bt709Limited || e == YuvEncoding::Bt709Full,
				      e == YuvEncoding::Bt601Full || e == YuvEncoding::Bt709Full);
	// Where red sits in the top-left 2x2 block.
	raw_.redX = image.format == PixelFormat::BayerGRBG8 || image.format == PixelFormat::BayerBGGR8;
	raw_.redY = image.format == PixelFormat::BayerGBRG8 || image.format == PixelFormat::BayerBGGR8;
	k_ = k_ ? k_ : &kernels::bestConvertKernels();
	convert_ = converter();
}

int FrameInput::stripRows() const { return convert_ ? kStripRows : image_.height; }

const uint8_t *FrameInput::rows(int y0, int count, ptrdiff_t &stride)
{
	return rows(y0, count, stride, strip_.data());
}

const uint8_t *FrameInput::rows(int y0, int count, ptrdiff_t &stride, uint8_t *scratch) const
{
	if (!convert_) {
		stride = image_.strides[0];
		return image_.planes[0] + y0 * stride;
	}
	stride = ptrdiff_t(3) * image_.width;
	convert_(raw_, y0, count, scratch, stride);
	return scratch;
}

const uint8_t *FrameInput::wholeFrame(ptrdiff_t &stride)
{
	if (!convert_) {
		stride = image_.strides[0];
		return image_.planes[0];
	}
	stride = ptrdiff_t(3) * image_.width;
	convert_(raw_, 0, image_.height, whole_.data(), stride);
	return whole_.data();
}

} // namespace calped
