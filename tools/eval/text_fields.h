// SPDX-License-Identifier: BSD-2-Clause
// Strict parsing of the numeric text inputs (MOTChallenge ground truth, detection CSV):
// a field is a number only if all of it is, so "12a" or "" is an error, never a 12 or 0.
#pragma once

#include "file_io.h"

#include <string>
#include <string_view>
#include <vector>

namespace calped::eval_tool {

// Splits on commas and trims spaces, tabs and a trailing CR from each field.
std::vector<std::string> splitCsvLine(const std::string &line);

bool parseDouble(const std::string &text, double &out); // finite values only
bool parseLong(const std::string &text, long &out);     // decimal integer (also "12.0")

// Input text for a message: the core's excerpt (lib/src/text/excerpt.h: at most `max` bytes,
// "..." when cut, control bytes and bytes that are not UTF-8 as '?').
std::string printable(const std::string &text, size_t max = 60);

// "FILE:LINE: message", the form every reader uses for malformed input.
std::string lineError(const std::string &path, long line, const std::string &message);

// Reads a text file line by line; `onLine` returns false (with `error` set) to stop.
// Fails with a message naming the file if it cannot be opened or read.
template <typename F>
bool forEachLine(const std::string &path, std::string &error, F onLine);
// The same over text already in memory.
template <typename F>
bool forEachLineIn(std::string_view text, F onLine);

using apps::readTextFile;

template <typename F>
bool forEachLineIn(std::string_view text, F onLine)
{
	long lineNo = 0;
	size_t pos = 0;
	while (pos < text.size()) {
		size_t end = text.find('\n', pos);
		if (end == std::string_view::npos)
			end = text.size();
		lineNo++;
		if (!onLine(lineNo, std::string(text.substr(pos, end - pos))))
			return false;
		pos = end + 1;
	}
	return true;
}

template <typename F>
bool forEachLine(const std::string &path, std::string &error, F onLine)
{
	std::string text;
	if (!readTextFile(path, text, error))
		return false;
	return forEachLineIn(text, onLine);
}

} // namespace calped::eval_tool
