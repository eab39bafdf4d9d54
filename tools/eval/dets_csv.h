// SPDX-License-Identifier: BSD-2-Clause
// Detection CSV, "frame,x,y,w,h,score" (1-based frames, input pixels), as calped-detect
// writes it. Every value is written with as few digits as give the same double back, so
// scoring the file reproduces the in-memory evaluation exactly.
#pragma once

#include <string>
#include <string_view>

#include "boxes.h"

namespace calped::eval_tool {

// The shortest "%.Ng" (N >= 9) that reads back as exactly `v`.
std::string shortestDecimal(double v);

// The detector's float as the double nearest its 9-digit decimal form: the harness keeps
// detections so, and the CSV then holds short numbers that still read back exactly.
double floatAsDecimal(float v);

bool writeDetectionsCsv(const std::string &path, const SequenceDetections &detections,
			std::string &error);

// Largest frame number a detections CSV may hold when no maximum is given (a day at
// 10 frames per second; the table of frames is sized by it).
constexpr long kMaxDetectionsCsvFrame = 1000000;

// Reads a CSV with or without the header line. Frames must be whole numbers in
// 1..maxFrame (0: 1..kMaxDetectionsCsvFrame); `out` grows to the largest frame seen.
bool readDetectionsCsv(const std::string &path, long maxFrame, SequenceDetections &out,
		       std::string &error);
// The same over text in memory; `path` names it in messages (the fuzz target's entry).
bool parseDetectionsCsv(std::string_view text, const std::string &path, long maxFrame,
			SequenceDetections &out, std::string &error);

} // namespace calped::eval_tool
