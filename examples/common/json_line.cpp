// SPDX-License-Identifier: BSD-2-Clause
#include "json_line.h"

#include <cinttypes>
#include <cmath>

namespace calped {
namespace live {

void writeJsonLine(FILE *f, const ports::Frame &frame, double ms, const Detections &detections)
{
	std::fprintf(f, "{\"frame\":%" PRIu64 ",\"timestamp_ns\":%" PRId64
			",\"width\":%d,\"height\":%d,\"ms\":%.3f,\"detections\":[",
		     frame.id, frame.timestampNs, frame.image.width, frame.image.height, ms);
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
	std::fputs("]}\n", f);
	std::fflush(f); // live output: a reader sees each frame as it is processed
}

} // namespace live
} // namespace calped
