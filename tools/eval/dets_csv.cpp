// SPDX-License-Identifier: BSD-2-Clause
#include "dets_csv.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "text_fields.h"

namespace calped::eval_tool {

std::string shortestDecimal(double v)
{
	char buf[40];
	for (int digits = 9; digits < 17; digits++) {
		std::snprintf(buf, sizeof(buf), "%.*g", digits, v);
		if (std::strtod(buf, nullptr) == v)
			return buf;
	}
	std::snprintf(buf, sizeof(buf), "%.17g", v);
	return buf;
}

double floatAsDecimal(float v)
{
	char buf[40];
	std::snprintf(buf, sizeof(buf), "%.9g", static_cast<double>(v));
	return std::strtod(buf, nullptr);
}

bool writeDetectionsCsv(const std::string &path, const SequenceDetections &detections,
			std::string &error)
{
	FILE *f = std::fopen(path.c_str(), "w");
	if (!f) {
		error = "cannot write " + path + ": " + std::strerror(errno);
		return false;
	}
	std::fputs("frame,x,y,w,h,score\n", f);
	for (size_t k = 0; k < detections.size(); k++)
		for (const ScoredBox &d : detections[k])
			std::fprintf(f, "%zu,%s,%s,%s,%s,%s\n", k + 1, shortestDecimal(d.box.x).c_str(),
				     shortestDecimal(d.box.y).c_str(), shortestDecimal(d.box.w).c_str(),
				     shortestDecimal(d.box.h).c_str(), shortestDecimal(d.score).c_str());
	const bool ok = std::fflush(f) == 0 && !std::ferror(f);
	const int savedErrno = errno;
	if (std::fclose(f) != 0 || !ok) {
		error = "cannot write " + path + ": " +
			(savedErrno ? std::strerror(savedErrno) : "write error");
		return false;
	}
	return true;
}

bool readDetectionsCsv(const std::string &path, long maxFrame, SequenceDetections &out,
		       std::string &error)
{
	out.clear();
	std::string text;
	if (!readTextFile(path, text, error)) {
		if (error.rfind(path, 0) != 0)
			error = "detections: " + error;
		return false;
	}
	return parseDetectionsCsv(text, path, maxFrame, out, error);
}

bool parseDetectionsCsv(std::string_view text, const std::string &path, long maxFrame,
			SequenceDetections &out, std::string &error)
{
	out.clear();
	// Frames index a table: a number alone must not size it beyond any real sequence.
	const long lastFrame = maxFrame > 0 ? maxFrame : kMaxDetectionsCsvFrame;
	const bool ok = forEachLineIn(text, [&](long lineNo, const std::string &line) {
		if (line.find_first_not_of(" \t\r") == std::string::npos)
			return true;
		const std::vector<std::string> f = splitCsvLine(line);
		// calped-detect's CSV adds ground_x,ground_y,world_height (empty without a
		// calibration): accepted and not used.
		if (lineNo == 1 && !f.empty() && f[0] == "frame") {
			if ((f.size() == 6 || f.size() == 9) && f[1] == "x" && f[2] == "y" && f[3] == "w" &&
			    f[4] == "h" && f[5] == "score" &&
			    (f.size() == 6 || (f[6] == "ground_x" && f[7] == "ground_y" && f[8] == "world_height")))
				return true;
			error = lineError(path, lineNo, "header is not \"frame,x,y,w,h,score\" "
							"(or calped-detect's, with ground_x,ground_y,world_height)");
			return false;
		}
		if (f.size() != 6 && f.size() != 9) {
			error = lineError(path, lineNo, "expected 6 comma-separated fields "
							"(frame,x,y,w,h,score) or calped-detect's 9, got " +
								std::to_string(f.size()));
			return false;
		}
		static const char *const kNames[] = { "frame", "x", "y", "w", "h", "score" };
		double v[6];
		for (int i = 0; i < 6; i++) {
			if (!parseDouble(f[i], v[i])) {
				error = lineError(path, lineNo, std::string(kNames[i]) + " \"" + printable(f[i]) +
									"\" is not a finite number");
				return false;
			}
		}
		long frame;
		if (!parseLong(f[0], frame) || frame < 1) {
			error = lineError(path, lineNo, "frame \"" + printable(f[0]) +
								"\" is not a whole number >= 1 (frames are 1-based)");
			return false;
		}
		if (frame > lastFrame) {
			error = lineError(path, lineNo, "frame " + printable(f[0]) + " is beyond the " +
								std::to_string(lastFrame) +
								(maxFrame > 0 ? " frames scored" : " frames a detections file may hold"));
			return false;
		}
		if (static_cast<size_t>(frame) > out.size())
			out.resize(static_cast<size_t>(frame));
		ScoredBox d;
		d.box = Box{ v[1], v[2], v[3], v[4] };
		d.score = v[5];
		out[static_cast<size_t>(frame) - 1].push_back(d);
		return true;
	});
	if (!ok) {
		if (error.rfind(path, 0) != 0)
			error = "detections: " + error;
		out.clear();
	}
	return ok;
}

} // namespace calped::eval_tool
