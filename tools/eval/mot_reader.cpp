// SPDX-License-Identifier: BSD-2-Clause
// MOTChallenge gt.txt: frame,id,x,y,w,h,flag,class,visibility (frames 1-based). Only the
// flag column matters here: 0 marks a box to ignore (a static person, a reflection...).
// Class and visibility are checked to be numbers but otherwise not used.
#include "ground_truth.h"

#include "text_fields.h"

namespace calped::eval_tool {

bool readMotGroundTruth(const std::string &path, GroundTruth &out, std::string &error)
{
	out = GroundTruth();
	std::string text;
	if (!readTextFile(path, text, error)) {
		error = "ground truth: " + error;
		return false;
	}
	return parseMotGroundTruth(text.data(), text.size(), path, out, error);
}

bool parseMotGroundTruth(const char *data, size_t size, const std::string &path,
			 GroundTruth &out, std::string &error)
{
	out = GroundTruth();
	long boxes = 0;
	const bool ok = forEachLineIn(std::string_view(data, size), [&](long lineNo, const std::string &line) {
		if (line.find_first_not_of(" \t\r") == std::string::npos)
			return true; // blank lines (a final newline, spacing) carry nothing
		const std::vector<std::string> f = splitCsvLine(line);
		if (f.size() < 6 || f.size() > 10) {
			error = lineError(path, lineNo,
					  "expected 6 to 10 comma-separated fields "
					  "(frame,id,x,y,w,h,flag,class,visibility), got " +
						  std::to_string(f.size()));
			return false;
		}
		static const char *const kNames[] = { "frame", "id", "x", "y", "w", "h",
						      "flag", "class", "visibility", "field 10" };
		double v[10];
		for (size_t i = 0; i < f.size(); i++) {
			if (!parseDouble(f[i], v[i])) {
				error = lineError(path, lineNo,
						  std::string(kNames[i]) + " \"" + printable(f[i]) +
							  "\" is not a number");
				return false;
			}
		}
		long frame;
		if (!parseLong(f[0], frame) || frame < 1) {
			error = lineError(path, lineNo,
					  "frame \"" + printable(f[0]) +
						  "\" is not a whole number >= 1 (MOTChallenge frames are "
						  "1-based)");
			return false;
		}
		if (!(v[4] > 0 && v[5] > 0)) {
			error = lineError(path, lineNo,
					  "box size w=" + printable(f[4]) + " h=" + printable(f[5]) +
						  " is not positive");
			return false;
		}
		GtBox b;
		b.box = Box{ v[2], v[3], v[4], v[5] };
		b.ignore = f.size() >= 7 && v[6] == 0;
		out.add(frame, b);
		boxes++;
		return true;
	});
	if (!ok) {
		out = GroundTruth();
		return false;
	}
	if (boxes == 0) {
		error = path + ": no boxes: empty MOTChallenge ground truth";
		return false;
	}
	return true;
}

} // namespace calped::eval_tool
