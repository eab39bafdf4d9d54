// SPDX-License-Identifier: BSD-2-Clause
// The CSV and JSON Lines outputs. Write errors are reported, not ignored: a full disk
// must not produce a silently truncated result file.
#pragma once

#include <cstdio>
#include <string>

#include <calped/detector.h>

#include "atomic_file.h"

namespace calped::apps {

class OutputFile
{
public:
	OutputFile() = default;
	~OutputFile();
	OutputFile(const OutputFile &) = delete;
	OutputFile &operator=(const OutputFile &) = delete;

	// "-" opens standard output. A file is written beside its name and renamed into place
	// by close(): a failed run leaves what was there before (ports/file/atomic_file.h).
	bool open(const std::string &path, std::string &error);
	bool isOpen() const { return file_ != nullptr; }
	FILE *get() { return file_; }
	// Flushes and closes (a file: renamed into place); fails if any earlier write failed.
	bool close(std::string &error);

private:
	FILE *file_ = nullptr;
	ports::AtomicFile atomic_; // a file: written beside its name, renamed by close()
	std::string path_;
	bool isStdout_ = false;
};

// CSV: header "frame,x,y,w,h,score,ground_x,ground_y,world_height", one row per
// detection; the three world fields are empty without a calibration (docs/cli.md).
void writeCsvHeader(FILE *f);
void writeCsvRows(FILE *f, long frame, const Detections &detections);

// MOTChallenge detections (det.txt): "frame,-1,x,y,w,h,score,ground_x,ground_y,world_height"
// without a header; the world fields are -1 without a calibration.
void writeMotRows(FILE *f, long frame, const Detections &detections);

// The overlay image name of a frame, the same in every program: "000042.png" (six digits
// at least).
std::string overlayFileName(long long frame);

} // namespace calped::apps
