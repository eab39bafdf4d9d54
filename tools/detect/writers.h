// SPDX-License-Identifier: BSD-2-Clause
// The CSV and JSON Lines outputs. Write errors are reported, not ignored: a full disk
// must not produce a silently truncated result file.
#pragma once

#include <cstdio>
#include <string>

#include <calped/detector.h>

namespace calped::detect_tool {

class OutputFile
{
public:
	OutputFile() = default;
	~OutputFile();
	OutputFile(const OutputFile &) = delete;
	OutputFile &operator=(const OutputFile &) = delete;

	// "-" opens standard output.
	bool open(const std::string &path, std::string &error);
	bool isOpen() const { return file_ != nullptr; }
	FILE *get() { return file_; }
	// Flushes and closes; fails if any earlier write failed.
	bool close(std::string &error);

private:
	FILE *file_ = nullptr;
	std::string path_;
	bool isStdout_ = false;
};

// CSV: header "frame,x,y,w,h,score", one row per detection.
void writeCsvHeader(FILE *f);
void writeCsvRows(FILE *f, long frame, const Detections &detections);

// One JSON object per frame on one line.
void writeJsonlFrame(FILE *f, long frame, const std::string &file, double ms,
		     const Detections &detections);

// JSON string literal for `text`, quotes included.
std::string jsonString(const std::string &text);

} // namespace calped::detect_tool
