// SPDX-License-Identifier: BSD-2-Clause
#include "ground_truth.h"

#include <string_view>

#include "text_fields.h"

namespace calped::eval_tool {

void GroundTruth::add(long frame, const GtBox &box)
{
	if (frame < 1)
		return; // readers reject these first
	frames_[frame].push_back(box);
}

const std::vector<GtBox> &GroundTruth::boxes(long frame) const
{
	static const std::vector<GtBox> kNone;
	auto it = frames_.find(frame);
	return it == frames_.end() ? kNone : it->second;
}

long GroundTruth::count(long upTo, bool ignore) const
{
	long n = 0;
	for (auto it = frames_.begin(); it != frames_.end() && it->first <= upTo; ++it)
		for (const GtBox &b : it->second)
			n += b.ignore == ignore;
	return n;
}

bool loadGroundTruth(const std::string &path, GroundTruth &out, std::string &error)
{
	std::string text;
	if (!readTextFile(path, text, error)) {
		out = GroundTruth();
		error = "ground truth: " + error;
		return false;
	}
	return parseGroundTruth(text.data(), text.size(), path, out, error);
}

bool parseGroundTruth(const char *data, size_t size, const std::string &name, GroundTruth &out,
		      std::string &error)
{
	const std::string_view text(data, size);
	size_t i = 0;
	// Skip a UTF-8 byte order mark and leading white space before sniffing.
	if (text.substr(0, 3) == "\xEF\xBB\xBF")
		i = 3;
	while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n'))
		i++;
	if (i < text.size() && text[i] == '<')
		return parseCvmlGroundTruth(data, size, name, out, error);
	return parseMotGroundTruth(data, size, name, out, error);
}

} // namespace calped::eval_tool
