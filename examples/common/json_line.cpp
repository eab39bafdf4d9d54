// SPDX-License-Identifier: BSD-2-Clause
#include "json_line.h"

#include <cinttypes>

#include "json_detections.h"

namespace calped {
namespace live {

void writeJsonLine(FILE *f, const ports::Frame &frame, double ms, const Detections &detections)
{
	std::fprintf(f, "{\"frame\":%" PRIu64 ",\"timestamp_ns\":%" PRId64
			",\"width\":%d,\"height\":%d,\"ms\":%.3f,\"detections\":",
		     frame.id, frame.timestampNs, frame.image.width, frame.image.height, ms);
	detect_tool::writeJsonDetections(f, detections);
	std::fputs("}\n", f);
	std::fflush(f); // live output: a reader sees each frame as it is processed
}

} // namespace live
} // namespace calped
