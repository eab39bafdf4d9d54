// SPDX-License-Identifier: BSD-2-Clause
#include "calib/text_util.h"

#include "text/excerpt.h"

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
	return excerpt(s, buffer, size);
}

Status fileError(ErrorCode code, const char *name, int line, const char *fmt, ...)
{
	char text[224];
	va_list args;
	va_start(args, fmt);
	std::vsnprintf(text, sizeof(text), fmt, args);
	va_end(args);
	// The name is the caller's (a path, a user's label): escaped like any input.
	char quotedName[kExcerptPathBytes + 4];
	excerpt(name ? name : "", quotedName, sizeof(quotedName), kExcerptPathBytes);
	if (line > 0)
		return Status::error(code, "%s:%d: %s", quotedName, line, text);
	return Status::error(code, "%s: %s", quotedName, text);
}

Status numberError(NumberResult r, const char *name, int line, const char *field,
		   std::string_view token)
{
	char q[kExcerptBytes + 4];
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
	char quotedName[kExcerptPathBytes + 4];
	excerpt(name ? name : "", quotedName, sizeof(quotedName), kExcerptPathBytes);
	return Status::error(st.code(), "%s: %s", quotedName, text);
}

} // namespace calped::calib
