// SPDX-License-Identifier: BSD-2-Clause
#include "json_detections.h"

#include <cmath>

namespace calped::detect_tool {

void writeJsonDetections(FILE *f, const Detections &detections)
{
	std::fputc('[', f);
	bool first = true;
	for (const Detection &d : detections) {
		std::fprintf(f, "%s{\"x\":%.2f,\"y\":%.2f,\"w\":%.2f,\"h\":%.2f,\"score\":%.4f",
			     first ? "" : ",", d.x, d.y, d.w, d.h, d.score);
		// With a calibration: where the person stands (metres) and how tall the box is.
		if (std::isfinite(d.groundX) && std::isfinite(d.groundY))
			std::fprintf(f, ",\"ground_x\":%.3f,\"ground_y\":%.3f", d.groundX, d.groundY);
		if (std::isfinite(d.worldHeight))
			std::fprintf(f, ",\"world_height\":%.3f", d.worldHeight);
		std::fputc('}', f);
		first = false;
	}
	std::fputc(']', f);
}

} // namespace calped::detect_tool
