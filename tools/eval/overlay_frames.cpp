// SPDX-License-Identifier: BSD-2-Clause
#include "overlay_frames.h"

#include <cmath>
#include <cstdio>

#include "overlay.h"

namespace calped::eval_tool {

ports::RgbImage renderEvaluationOverlay(const ports::RgbImage &frame,
					      const std::vector<GtBox> &truth,
					      const std::vector<ScoredBox> &detections,
					      double minScore)
{
	static const uint8_t kBlue[3] = { 40, 90, 255 };
	static const uint8_t kGrey[3] = { 160, 160, 160 };
	static const uint8_t kGreen[3] = { 0, 230, 0 };
	ports::RgbImage out = frame;
	for (const GtBox &g : truth)
		apps::drawRectangle(out, static_cast<float>(g.box.x), static_cast<float>(g.box.y),
					   static_cast<float>(g.box.w), static_cast<float>(g.box.h), 2,
					   g.ignore ? kGrey : kBlue);
	for (const ScoredBox &d : detections)
		if (d.score >= minScore)
			apps::drawRectangle(out, static_cast<float>(d.box.x),
						   static_cast<float>(d.box.y), static_cast<float>(d.box.w),
						   static_cast<float>(d.box.h), 2, kGreen);
	return out;
}

std::string resizeLabel(double resize)
{
	char buf[32];
	if (std::fabs(resize * 10 - std::round(resize * 10)) < 1e-9)
		std::snprintf(buf, sizeof(buf), "%.1f", resize);
	else
		std::snprintf(buf, sizeof(buf), "%g", resize);
	return buf;
}

std::string runStem(const std::string &method, double resize)
{
	return method + "_r" + resizeLabel(resize);
}

} // namespace calped::eval_tool
