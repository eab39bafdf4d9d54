// SPDX-License-Identifier: BSD-2-Clause
#include "search/window_boxes.h"

#include <cmath>

namespace calped {

WindowBoxes::WindowBoxes(const ModelParams &p, double frameResize)
	: shiftH_((p.modelDsPadH - double(p.modelDsH)) / 2 - p.padH),
	  shiftW_((p.modelDsPadW - double(p.modelDsW)) / 2 - p.padW), resize_(frameResize),
	  stride_(p.stride), modelH_(p.modelDsH), modelW_(p.modelDsW)
{
}

WindowBox WindowBoxes::box(const PyramidLevel &l, int row, int col) const
{
	WindowBox b;
	b.x = (col * stride_ + shiftW_) / l.scaleW / resize_;
	b.y = (row * stride_ + shiftH_) / l.scaleH / resize_;
	b.w = modelW_ / l.scale / resize_;
	b.h = modelH_ / l.scale / resize_;
	return b;
}

void WindowBoxes::centredIn(const PyramidLevel &l, float x0, float y0, float x1, float y1, int &r0,
			    int &r1, int &c0, int &c1) const
{
	const double w = modelW_ / l.scale / resize_, h = modelH_ / l.scale / resize_;
	// box() solved for the column: x = (c * stride + shiftW) / scaleW / resize, with the
	// centre x + w / 2 in [x0, x1].
	const double kx = l.scaleW * resize_, ky = l.scaleH * resize_;
	c0 = int(std::ceil(((x0 - w / 2) * kx - shiftW_) / stride_));
	c1 = int(std::floor(((x1 - w / 2) * kx - shiftW_) / stride_));
	r0 = int(std::ceil(((y0 - h / 2) * ky - shiftH_) / stride_));
	r1 = int(std::floor(((y1 - h / 2) * ky - shiftH_) / stride_));
}

} // namespace calped
