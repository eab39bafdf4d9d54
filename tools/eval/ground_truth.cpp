// SPDX-License-Identifier: BSD-2-Clause
#include "ground_truth.h"

#include "text_fields.h"

namespace calped::eval_tool {

void GroundTruth::add(long frame, const GtBox &box)
{
	if (frame < 1)
		return; // readers reject these first; never index out of range
	if (static_cast<size_t>(frame) > frames_.size())
		frames_.resize(static_cast<size_t>(frame));
	frames_[static_cast<size_t>(frame) - 1].push_back(box);
}

const std::vector<GtBox> &GroundTruth::boxes(long frame) const
{
	static const std::vector<GtBox> kNone;
	if (frame < 1 || static_cast<size_t>(frame) > frames_.size())
		return kNone;
	return frames_[static_cast<size_t>(frame) - 1];
}

long GroundTruth::count(long upTo, bool ignore) const
{
	long n = 0;
	for (long f = 1; f <= upTo && f <= lastFrame(); f++)
		for (const GtBox &b : boxes(f))
			n += b.ignore == ignore;
	return n;
}

bool loadGroundTruth(const std::string &path, GroundTruth &out, std::string &error)
{
	std::string text;
	if (!readTextFile(path, text, error)) {
		error = "ground truth: " + error;
		return false;
	}
	size_t i = 0;
	// Skip a UTF-8 byte order mark and leading white space before sniffing.
	if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
		i = 3;
	while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n'))
		i++;
	if (i < text.size() && text[i] == '<')
		return readCvmlGroundTruth(path, out, error);
	return readMotGroundTruth(path, out, error);
}

} // namespace calped::eval_tool
