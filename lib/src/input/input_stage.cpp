// SPDX-License-Identifier: BSD-2-Clause
#include "input/input_stage.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace calped {

int resizedSize(int size, double resize) { return int(std::lround(size * resize)); }

Status InputStage::init(int maxWidth, int maxHeight, double frameResize)
{
	frameResize_ = frameResize;
	maxWidth_ = maxWidth;
	maxHeight_ = maxHeight;
	const bool resizing = frameResize != 1.0;
	// Camera formats are converted a strip at a time, or whole before a frame resize.
	Status st = input_.init(maxWidth, maxHeight, resizing);
	if (!st.ok() || !resizing)
		return st;
	const int w1 = resizedSize(maxWidth, frameResize), h1 = resizedSize(maxHeight, frameResize);
	try {
		resized_.assign(size_t(w1) * h1 * 3, 0);
		const size_t taps = size_t(std::max(w1, h1)) + 8;
		tapsX_.resize(taps);
		tapsY_.resize(taps);
		rowScratch_.assign(size_t(maxWidth) * 3 + 8, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "input resize buffers");
	}
	tapsForMax_ = kernels::buildResampleTaps(maxWidth, w1, 1.0, tapsX_.data()) &&
		      kernels::buildResampleTaps(maxHeight, h1, 1.0, tapsY_.data());
	return Status::success();
}

FrameInput &InputStage::begin(const ImageView &image)
{
	width_ = image.width;
	height_ = image.height;
	input_.begin(image);
	return input_;
}

Status InputStage::resize()
{
	if (frameResize_ == 1.0)
		return Status::success();
	// The resampler reads a whole RGB8 image: other formats are converted first.
	ptrdiff_t stride;
	const uint8_t *rgb = input_.wholeFrame(stride);
	const int w1 = resizedSize(width_, frameResize_), h1 = resizedSize(height_, frameResize_);
	if (w1 < 1 || h1 < 1)
		return Status::error(ErrorCode::ImageTooSmall, "resize leaves no pixels");
	// init() built the taps of maximum-size frames; other sizes build their own.
	const bool maxSize = width_ == maxWidth_ && height_ == maxHeight_;
	if (!(maxSize && tapsForMax_)) {
		tapsForMax_ = false;
		if (!kernels::buildResampleTaps(width_, w1, 1.0, tapsX_.data()) ||
		    !kernels::buildResampleTaps(height_, h1, 1.0, tapsY_.data()))
			return Status::error(ErrorCode::InvalidArgument, "resize ratio too small");
		tapsForMax_ = maxSize;
	}
	kernels::bestKernels().resampleRgb8(rgb, stride, width_, height_, resized_.data(), 3 * w1, w1,
					    h1, tapsX_.data(), tapsY_.data(), rowScratch_.data());
	input_.begin(ImageView::rgb8(resized_.data(), w1, h1));
	return Status::success();
}

} // namespace calped
