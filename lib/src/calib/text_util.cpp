// SPDX-License-Identifier: BSD-2-Clause
#include "calib/text_util.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <charconv>

namespace calped::calib {

bool LineReader::next(std::string_view &line)
{
	if (pos_ >= text_.size())
		return false;
	size_t end = text_.find('\n', pos_);
	if (end == std::string_view::npos)
		end = text_.size();
	line = text_.substr(pos_, end - pos_);
	if (!line.empty() && line.back() == '\r')
		line.remove_suffix(1);
	pos_ = end + 1;
	line_++;
	return true;
}

std::string_view trim(std::string_view s)
{
	const char *space = " \t\r\n\f\v";
	size_t b = s.find_first_not_of(space);
	if (b == std::string_view::npos)
		return {};
	size_t e = s.find_last_not_of(space);
	return s.substr(b, e - b + 1);
}

std::string_view stripComment(std::string_view s)
{
	size_t hash = s.find('#');
	return hash == std::string_view::npos ? s : s.substr(0, hash);
}

bool startsWith(std::string_view s, std::string_view prefix)
{
	return s.substr(0, prefix.size()) == prefix;
}

NumberResult parseNumber(std::string_view s, double &out)
{
	if (s.empty())
		return NumberResult::NotANumber;
	const char *b = s.data();
	const char *e = s.data() + s.size();
	// from_chars takes no leading '+'; a sign must be followed by the number itself.
	if (*b == '+') {
		b++;
		if (b == e || *b == '-' || *b == '+')
			return NumberResult::NotANumber;
	}
	double v = 0;
	std::from_chars_result r = std::from_chars(b, e, v, std::chars_format::general);
	if (r.ec == std::errc::result_out_of_range)
		return NumberResult::NotFinite;
	if (r.ec != std::errc() || r.ptr != e)
		return NumberResult::NotANumber;
	if (!std::isfinite(v))
		return NumberResult::NotFinite;
	out = v;
	return NumberResult::Ok;
}

const char *quote(std::string_view s, char *buffer, size_t size)
{
	if (size == 0)
		return "";
	size_t n = s.size();
	size_t copied = n;
	if (n < size) {
		if (n > 0) // an empty view may have no data pointer at all
			std::memcpy(buffer, s.data(), n);
		buffer[n] = '\0';
	} else {
		copied = size > 4 ? size - 4 : 0;
		std::memcpy(buffer, s.data(), copied);
		std::memcpy(buffer + copied, "...", size - copied > 3 ? 4 : size - copied);
		buffer[size - 1] = '\0';
	}
	// Messages are one printable line: control bytes from the input (NUL too) become '?'.
	for (size_t i = 0; i < copied; i++)
		if (static_cast<unsigned char>(buffer[i]) < 0x20 || buffer[i] == 0x7f)
			buffer[i] = '?';
	return buffer;
}

Status fileError(ErrorCode code, const char *name, int line, const char *fmt, ...)
{
	char text[224];
	va_list args;
	va_start(args, fmt);
	std::vsnprintf(text, sizeof(text), fmt, args);
	va_end(args);
	if (line > 0)
		return Status::error(code, "%s:%d: %s", name, line, text);
	return Status::error(code, "%s: %s", name, text);
}

Status numberError(NumberResult r, const char *name, int line, const char *field,
		   std::string_view token)
{
	char q[48];
	quote(token, q, sizeof(q));
	if (r == NumberResult::NotFinite)
		return fileError(ErrorCode::ParseError, name, line, "%s '%s' is not a finite number",
				 field, q);
	return fileError(ErrorCode::ParseError, name, line, "%s '%s' is not a number", field, q);
}

Status withFileName(const Status &st, const char *name)
{
	if (st.ok())
		return st;
	const char *text = st.message();
	const size_t skip = std::strlen(errorCodeName(st.code())) + 2; // "Code: "
	if (std::strlen(text) >= skip)
		text += skip;
	return Status::error(st.code(), "%s: %s", name, text);
}

} // namespace calped::calib
