// SPDX-License-Identifier: BSD-2-Clause
#include "writers.h"

#include <cerrno>
#include <cmath>
#include <cstring>

namespace calped::apps {

OutputFile::~OutputFile() = default; // a file not closed: atomic_ removes the temporary

bool OutputFile::open(const std::string &path, std::string &error)
{
	path_ = path;
	if (path == "-") {
		file_ = stdout;
		isStdout_ = true;
		return true;
	}
	if (!atomic_.open(path, error))
		return false;
	file_ = atomic_.get();
	return true;
}

bool OutputFile::close(std::string &error)
{
	if (!file_)
		return true;
	file_ = nullptr;
	if (!isStdout_)
		return atomic_.commit(error);
	errno = 0;
	const bool ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
	if (!ok)
		error = std::string("cannot write standard output: ") + (errno ? std::strerror(errno) : "write error");
	return ok;
}

void writeCsvHeader(FILE *f)
{
	std::fputs("frame,x,y,w,h,score,ground_x,ground_y,world_height\n", f);
}

namespace {

// One row per detection: the frame (and MOT's id -1), the box and score, then the world
// fields or `missing` for each.
void writeRows(FILE *f, long frame, const Detections &detections, bool mot)
{
	const char *missing = mot ? "-1" : "";
	for (const Detection &d : detections) {
		std::fprintf(f, mot ? "%ld,-1,%.2f,%.2f,%.2f,%.2f,%.4f," : "%ld,%.2f,%.2f,%.2f,%.2f,%.4f,",
			     frame, d.x, d.y, d.w, d.h, d.score);
		if (std::isfinite(d.groundX) && std::isfinite(d.groundY))
			std::fprintf(f, "%.3f,%.3f,", d.groundX, d.groundY);
		else
			std::fprintf(f, "%s,%s,", missing, missing);
		if (std::isfinite(d.worldHeight))
			std::fprintf(f, "%.3f\n", d.worldHeight);
		else
			std::fprintf(f, "%s\n", missing);
	}
}

} // namespace

void writeCsvRows(FILE *f, long frame, const Detections &detections)
{
	writeRows(f, frame, detections, false);
}

void writeMotRows(FILE *f, long frame, const Detections &detections)
{
	writeRows(f, frame, detections, true);
}

std::string overlayFileName(long long frame)
{
	char name[32];
	std::snprintf(name, sizeof(name), "%06lld.png", frame);
	return name;
}

} // namespace calped::apps
