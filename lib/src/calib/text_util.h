// SPDX-License-Identifier: BSD-2-Clause
// Small helpers shared by the calibration text loaders: lines, tokens, strict numbers and
// error messages that name the file and line.
#pragma once

#include <cstddef>
#include <string_view>

#include "text/excerpt.h"

#include <calped/calibration.h>
#include <calped/status.h>

namespace calped::calib {

// Walks a buffer line by line (LF or CRLF), counting from 1.
class LineReader
{
public:
	LineReader(const char *data, size_t size) : text_(data, size) {}
	// False at the end of the buffer.
	bool next(std::string_view &line);
	int lineNumber() const { return line_; }

private:
	std::string_view text_;
	size_t pos_ = 0;
	int line_ = 0;
};

std::string_view trim(std::string_view s);
// The part of a line before '#'.
std::string_view stripComment(std::string_view s);
bool startsWith(std::string_view s, std::string_view prefix);

enum class NumberResult { Ok, NotANumber, NotFinite };
// The whole of `s` must be one decimal number (optional sign, exponent); locale-independent.
NumberResult parseNumber(std::string_view s, double &out);

// `s` quoted for a message in `buffer` (text/excerpt.h: at most 60 bytes and what fits,
// "..." when cut, '?' for control bytes and bytes that are not UTF-8).
const char *quote(std::string_view s, char *buffer, size_t size);

// "name:line: message" (line 0 leaves the line out).
Status fileError(ErrorCode code, const char *name, int line, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 4, 5)))
#endif
	;

// Error for a number field that did not parse, e.g. "'abc' is not a number".
Status numberError(NumberResult r, const char *name, int line, const char *field,
		   std::string_view token);

// `st` with "name: " put in front of its text (for errors from CameraModel's factories).
Status withFileName(const Status &st, const char *name);

} // namespace calped::calib
