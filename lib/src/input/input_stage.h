// SPDX-License-Identifier: BSD-2-Clause
// The input stage: a camera frame in any pixel format as RGB8 rows (FrameInput), and,
// when the resize is done on the frame (ResizeAt::Frame), the frame resampled first as
// the toolbox's imResample does. The pyramid then converts what it reads to LUV.
#pragma once

#include <calped/image.h>
#include <calped/status.h>

#include <vector>

#include "input/frame_input.h"
#include "kernels.h"

namespace calped {

class InputStage
{
public:
	// Frames up to maxWidth x maxHeight, resized by frameResize (1: not at all).
	Status init(int maxWidth, int maxHeight, double frameResize);

	// Takes a frame that passed checkImageLayout() and fits: frame() reads its own pixels.
	FrameInput &begin(const ImageView &image);
	// With a frame resize, resamples it: frame() reads the resized image from then on.
	Status resize();
	FrameInput &frame() { return input_; }

private:
	FrameInput input_;
	double frameResize_ = 1.0;
	int maxWidth_ = 0, maxHeight_ = 0; // of the input frame
	int width_ = 0, height_ = 0;       // of this frame
	std::vector<uint8_t> resized_;
	std::vector<kernels::ResampleTap> tapsX_, tapsY_;
	std::vector<int32_t> rowScratch_;
	bool tapsForMax_ = false; // tapsX_/Y_ hold the taps of maximum-size frames
};

// round(size * resize): a frame's size after the input resize.
int resizedSize(int size, double resize);

} // namespace calped
