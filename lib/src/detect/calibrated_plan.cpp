// SPDX-License-Identifier: BSD-2-Clause
#include "detect/calibrated_plan.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <new>

#include "detect/classifier.h"

namespace calped {

void windowBox(const ModelParams &p, const PyramidLevel &l, const WindowGeometry &g, int row,
	       int col, double &x, double &y, double &w, double &h)
{
	x = (col * p.stride + g.shiftW) / l.scaleW / g.resize;
	y = (row * p.stride + g.shiftH) / l.scaleH / g.resize;
	w = p.modelDsW / l.scale / g.resize;
	h = p.modelDsH / l.scale / g.resize;
}

double smallestNecessaryScale(const CameraModel &camera, int width, int height,
			      double modelHeight, double maxHeight)
{
	double tallest = NAN;
	for (const double u : { 0.0, double(width - 1) }) {
		const Eigen::Vector2d foot(u, height - 1);
		for (double h = modelHeight; h <= 4.0 * height; h += 1.0) {
			const double world = camera.boxWorldHeight(foot, Eigen::Vector2d(u, foot.y() - h));
			if (std::isnan(world))
				break;
			if (world >= maxHeight) {
				tallest = std::isnan(tallest) ? h : std::max(tallest, h);
				break;
			}
		}
	}
	return modelHeight / tallest;
}

int thesisScaleList(double smallest, int scalesPerOctave, double *out, int capacity)
{
	int n = 0;
	for (double octave = 1.0; octave >= smallest && octave > 1e-6; octave /= 2) {
		for (int k = 0; k < scalesPerOctave; k++) {
			const double s = octave - k * (octave / 2) / scalesPerOctave;
			if (s < smallest || n == capacity)
				return n;
			out[n++] = s;
		}
	}
	return n;
}

Status CalibratedPlan::build(const CameraModel &camera, const ModelParams &params,
			     const ScaleList &scales, double resize, int padH, int padW,
			     const Classifier &classifier, double minHeight, double maxHeight)
{
	if (!camera.valid())
		return Status::error(ErrorCode::InvalidArgument, "calibrated mode needs a valid camera");
	if (!(minHeight > 0 && maxHeight >= minHeight && maxHeight < 10))
		return Status::error(ErrorCode::InvalidArgument,
				     "pedestrian heights %g..%g m are not a range in (0, 10)", minHeight,
				     maxHeight);
	WindowGeometry g;
	g.shiftH = (params.modelDsPadH - double(params.modelDsH)) / 2 - params.padH;
	g.shiftW = (params.modelDsPadW - double(params.modelDsW)) / 2 - params.padW;
	g.resize = resize;
	try {
		windows_.clear();
		for (int i = 0; i < scales.count; i++) {
			first_[i] = windows_.size();
			const PyramidLevel &l = scales.levels[i];
			int rows, cols;
			classifier.windowGrid(l.height + 2 * padH, l.width + 2 * padW, rows, cols);
			if (rows > 65535 || cols > 65535)
				return Status::error(ErrorCode::InvalidArgument, "level %d too large", i);
			for (int c = 0; c < cols; c++)
				for (int r = 0; r < rows; r++) {
					double x, y, w, h;
					windowBox(params, l, g, r, c, x, y, w, h);
					const Eigen::Vector2d foot(x + w / 2, y + h), head(x + w / 2, y);
					const double height = camera.boxWorldHeight(foot, head);
					if (height >= minHeight && height <= maxHeight)
						windows_.push_back(uint32_t(r) << 16 | uint32_t(c));
				}
		}
		first_[scales.count] = windows_.size();
		windows_.shrink_to_fit();
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "calibrated window lists");
	}
	return Status::success();
}

} // namespace calped
