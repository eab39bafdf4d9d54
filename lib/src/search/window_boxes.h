// SPDX-License-Identifier: BSD-2-Clause
// The one map from a classifier window of a pyramid level to the box it stands for in
// input-image pixels: the model's central (unpadded) window, shifted back by the
// padding, scaled by the level and the input resize. The detector's boxes, the
// calibrated plan's plausibility test and the static gate all use it.
#pragma once

#include <calped/model.h>

#include "pyramid/scales.h"

namespace calped {

struct WindowBox {
	double x = 0, y = 0, w = 0, h = 0;
};

class WindowBoxes
{
public:
	WindowBoxes() = default;
	// frameResize: the factor the frame itself was resized by before the pyramid (1 when
	// the resize is inside the pyramid, whose levels then carry it).
	WindowBoxes(const ModelParams &params, double frameResize);

	// Window (row, col) of level l (row and column in window steps of the padded level).
	WindowBox box(const PyramidLevel &l, int row, int col) const;
	// Its inverse for box centres: the window rows r0..r1 and columns c0..c1 of level l
	// whose box centre lies in the input-image rectangle [x0, x1] x [y0, y1] (not
	// clipped to the level's window grid).
	void centredIn(const PyramidLevel &l, float x0, float y0, float x1, float y1, int &r0,
		       int &r1, int &c0, int &c1) const;

private:
	double shiftH_ = 0, shiftW_ = 0; // window origin to box corner, level pixels
	double resize_ = 1;
	int32_t stride_ = 4;
	float modelH_ = 0, modelW_ = 0;
};

} // namespace calped
