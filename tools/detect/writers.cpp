// SPDX-License-Identifier: BSD-2-Clause
#include "writers.h"

#include "json_detections.h"

#include <cerrno>
#include <cmath>
#include <cstring>

namespace calped::detect_tool {

OutputFile::~OutputFile()
{
	if (file_ && !isStdout_)
		std::fclose(file_);
}

bool OutputFile::open(const std::string &path, std::string &error)
{
	path_ = path;
	if (path == "-") {
		file_ = stdout;
		isStdout_ = true;
		return true;
	}
	file_ = std::fopen(path.c_str(), "w");
	if (!file_) {
		error = "cannot write " + path + ": " + std::strerror(errno);
		return false;
	}
	return true;
}

bool OutputFile::close(std::string &error)
{
	if (!file_)
		return true;
	errno = 0;
	bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
	int savedErrno = errno;
	if (!isStdout_)
		ok = (std::fclose(file_) == 0) && ok;
	file_ = nullptr;
	if (!ok) {
		const char *why = savedErrno ? std::strerror(savedErrno) : "write error";
		error = "cannot write " + (isStdout_ ? std::string("standard output") : path_) + ": " + why;
	}
	return ok;
}

void writeCsvHeader(FILE *f)
{
	std::fputs("frame,x,y,w,h,score\n", f);
}

void writeCsvRows(FILE *f, long frame, const Detections &detections)
{
	for (const Detection &d : detections)
		std::fprintf(f, "%ld,%.2f,%.2f,%.2f,%.2f,%.4f\n", frame, d.x, d.y, d.w, d.h, d.score);
}

std::string jsonString(const std::string &text)
{
	std::string out = "\"";
	for (unsigned char c : text) {
		switch (c) {
		case '"': out += "\\\""; break;
		case '\\': out += "\\\\"; break;
		case '\n': out += "\\n"; break;
		case '\r': out += "\\r"; break;
		case '\t': out += "\\t"; break;
		default:
			if (c < 0x20) {
				char buf[8];
				std::snprintf(buf, sizeof(buf), "\\u%04x", c);
				out += buf;
			} else {
				out += static_cast<char>(c);
			}
		}
	}
	return out + "\"";
}

void writeJsonlFrame(FILE *f, long frame, const std::string &file, double ms,
		     const Detections &detections)
{
	std::fprintf(f, "{\"frame\":%ld,\"file\":%s,\"ms\":%.3f,\"detections\":", frame,
		     jsonString(file).c_str(), ms);
	writeJsonDetections(f, detections);
	std::fputs("}\n", f);
}

} // namespace calped::detect_tool
