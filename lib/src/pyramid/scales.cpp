// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/scales.h"

#include <algorithm>
#include <cmath>

namespace calped {

namespace {

// Matlab's round: halves away from zero.
double mround(double v) { return std::round(v); }

} // namespace

bool computeScales(const ModelParams &p, int height, int width, ScaleList &out, double upscale)
{
	out.count = 0;
	if (height <= 0 || width <= 0)
		return true;
	const double shrink = p.shrink;
	const double minRatio = std::min(height / double(p.minDsH), width / double(p.minDsW));
	const double octUp = p.nOctUp + std::log2(upscale);
	const int n = int(std::floor(p.nPerOct * (octUp + std::log2(minRatio)) + 1));
	if (n <= 0)
		return true;
	if (n > kMaxLevels)
		return false;

	// Nudge each scale so that both rounded dimensions land on multiples of shrink
	// with the least error, without changing the smaller dimension's rounding.
	const double d0 = std::min(height, width), d1 = std::max(height, width);
	double scales[kMaxLevels];
	for (int i = 0; i < n; i++) {
		const double s = std::pow(2.0, -double(i) / p.nPerOct + octUp);
		const double base = mround(d0 * s / shrink) * shrink;
		const double s0 = (base - 0.25 * shrink) / d0;
		const double s1 = (base + 0.25 * shrink) / d0;
		double best = 0, bestErr = INFINITY;
		for (int k = 0; k < 100; k++) {
			// The toolbox's (0:.01:1-eps): colon steps are k * 0.01.
			const double ss = (k * 0.01) * (s1 - s0) + s0;
			const double e0 = std::fabs(d0 * ss - mround(d0 * ss / shrink) * shrink);
			const double e1 = std::fabs(d1 * ss - mround(d1 * ss / shrink) * shrink);
			const double e = std::max(e0, e1);
			if (e < bestErr) {
				bestErr = e;
				best = ss;
			}
		}
		scales[i] = best;
	}

	// Drop repeated scales (keep the last of a run, like the toolbox).
	int count = 0;
	for (int i = 0; i < n; i++) {
		if (i + 1 < n && scales[i] == scales[i + 1])
			continue;
		PyramidLevel &l = out.levels[count++];
		l.scale = scales[i];
		l.height = int(mround(height * scales[i] / shrink));
		l.width = int(mround(width * scales[i] / shrink));
		l.scaleH = l.height * shrink / height;
		l.scaleW = l.width * shrink / width;
	}
	out.count = count;

	// Computed levels every nApprox+1, the others approximated from the nearest one.
	const int step = p.nApprox + 1;
	for (int i = 0; i < count; i++)
		out.levels[i].computed = (i % step) == 0;
	for (int i = 0; i < count; i++) {
		const int below = (i / step) * step;
		const int above = below + step;
		// Boundaries at floor((a + b) / 2) in the toolbox's 1-based indices.
		int src = below;
		if (above < count && (i + 1) > (below + 1 + above + 1) / 2)
			src = above;
		out.levels[i].source = src;
	}
	return true;
}

} // namespace calped
