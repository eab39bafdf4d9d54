// SPDX-License-Identifier: BSD-2-Clause
#include <calped/auto_resize.h>

#include <algorithm>
#include <cmath>

namespace calped {

Status chooseResize(const ModelParams &params, const CameraModel &camera, int width, int height,
		    const AutoResizeSettings &s, AutoResize &out)
{
	if (!camera.valid())
		return Status::error(ErrorCode::InvalidArgument, "automatic resize needs a valid camera");
	if (width < 1 || height < 1)
		return Status::error(ErrorCode::InvalidArgument, "automatic resize: frame %dx%d", width,
				     height);
	if (!(s.minPersonHeight > 0 && s.minPersonHeight < 10) || !(s.range > 0) || std::isnan(s.minFootRow) ||
	    !(s.minResize > 0 && s.minResize <= s.maxResize && s.maxResize <= 8))
		return Status::error(ErrorCode::InvalidArgument,
				     "automatic resize: person height %g m, range %g m, resize %g..%g",
				     s.minPersonHeight, s.range, s.minResize, s.maxResize);
	const Eigen::Vector3d centre = camera.centre();
	// Foot points on a grid of the frame (every 4th pixel, and the last row and column):
	// the box of a person of the smallest height standing there, if it lies in the frame.
	bool found = false;
	const int step = 4;
	for (int v = height - 1; v >= 0 && v >= s.minFootRow; v -= step) {
		for (int u = 0; u < width + step - 1; u += step) {
			const Eigen::Vector2d foot(std::min(u, width - 1), v);
			Eigen::Vector2d ground;
			if (!camera.pixelToGround(foot, ground))
				continue;
			const double distance = std::hypot(ground.x() - centre.x(), ground.y() - centre.y());
			if (distance > s.range)
				continue;
			const double h = camera.boxPixelHeight(foot, s.minPersonHeight);
			if (!(h > 0) || foot.y() - h < 0)
				continue;
			const double w = h * params.modelDsW / params.modelDsH;
			if (foot.x() - w / 2 < 0 || foot.x() + w / 2 > width)
				continue;
			if (!found || h < out.smallestPersonPixels) {
				out.smallestPersonPixels = h;
				out.footRow = foot.y();
				out.distance = distance;
				found = true;
			}
		}
	}
	if (!found)
		return Status::error(ErrorCode::InvalidArgument,
				     "automatic resize: no person of %g m fits in the %dx%d frame within %g m "
				     "of the camera (feet from row %g)",
				     s.minPersonHeight, width, height, s.range, s.minFootRow);
	const double raw = params.modelDsH / out.smallestPersonPixels;
	const int perOctave = std::max(1, int(params.nPerOct));
	// Rounded up to the scale step, so that the smallest person is at least the model's height.
	const double stepped = std::exp2(std::ceil(std::log2(raw) * perOctave - 1e-9) / perOctave);
	out.resize = std::clamp(stepped, s.minResize, s.maxResize);
	return Status::success();
}

} // namespace calped
