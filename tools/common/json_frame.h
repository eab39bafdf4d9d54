// SPDX-License-Identifier: BSD-2-Clause
// The one JSON frame record, written by calped-detect (--jsonl), calped-eval (--frames-jsonl)
// and the live programs (standard output), one object per line (docs/cli.md):
//   {"frame":N,"method":"calibrated"[,"camera_estimate":E][,"file":"..."][,"timestamp_ns":T],"width":W,
//    "height":H,"ms":M,"detections":[{"x":..,"y":..,"w":..,"h":..,"score":..
//    [,"ground_x":..,"ground_y":..][,"world_height":..]},...]}
// Strings are JSON-escaped (quotes, backslashes, every control character) and bytes that
// are not valid UTF-8 become U+FFFD, so any file name gives a valid line. fputc/fprintf
// only: nothing is allocated (the live loop writes it every frame).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include <calped/detector.h>

namespace calped::apps {

struct JsonFrame {
	long long frame = 0;
	const char *method = "generic";
	const char *file = nullptr; // the input file: written when not null
	int64_t timestampNs = -1;   // a live source's timestamp: written when >= 0
	int width = 0, height = 0;
	double ms = 0; // the detector's own time, FrameStats::msTotal
	int cameraEstimate = -1; // --calib auto: the camera estimate used (0: none yet); written when >= 0
};

// One line, newline included.
void writeJsonFrame(FILE *f, const JsonFrame &frame, const Detections &detections);

// The detections' array alone.
void writeJsonDetections(FILE *f, const Detections &detections);

// `text` as a JSON string literal, quotes included, escaped as above.
void writeJsonString(FILE *f, const char *text, size_t size);
std::string jsonString(const std::string &text);

} // namespace calped::apps
