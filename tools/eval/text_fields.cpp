// SPDX-License-Identifier: BSD-2-Clause
#include "text_fields.h"

#include "excerpt.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "args.h"
#include "file_io.h"

namespace calped::eval_tool {

namespace {

std::string trim(const std::string &s)
{
	size_t b = 0, e = s.size();
	while (b < e && (s[b] == ' ' || s[b] == '\t'))
		b++;
	while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r'))
		e--;
	return s.substr(b, e - b);
}

} // namespace

std::vector<std::string> splitCsvLine(const std::string &line)
{
	std::vector<std::string> fields;
	size_t pos = 0;
	for (;;) {
		size_t comma = line.find(',', pos);
		if (comma == std::string::npos) {
			fields.push_back(trim(line.substr(pos)));
			return fields;
		}
		fields.push_back(trim(line.substr(pos, comma - pos)));
		pos = comma + 1;
	}
}

bool parseDouble(const std::string &text, double &out)
{
	// Leading space is allowed in the data files (strtod's rule), not on command lines.
	const size_t start = text.find_first_not_of(" \t\n\r\f\v");
	return start != std::string::npos && apps::parseNumber(text.substr(start), out);
}

bool parseLong(const std::string &text, long &out)
{
	double v;
	// MOTChallenge files written by some tools hold "12.0" for integer columns.
	if (!parseDouble(text, v) || v != std::floor(v) || std::fabs(v) > 1e15)
		return false;
	out = static_cast<long>(v);
	return true;
}

std::string printable(const std::string &text, size_t max)
{
	return excerpt(text, max);
}

std::string lineError(const std::string &path, long line, const std::string &message)
{
	return excerpt(path, kExcerptPathBytes) + ":" + std::to_string(line) + ": " + message;
}

} // namespace calped::eval_tool
