// SPDX-License-Identifier: BSD-2-Clause
// Checks shared by the fuzz targets.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace calped::fuzz {

// An error message for people and logs: one line, no control characters (a field quoted
// from the input must not carry a newline or a terminal escape into it), well-formed UTF-8
// (no raw byte of the input that is not), not empty.
// Its own UTF-8 check, not the excerpt code's: the rule is tested, not the implementation.
inline bool printableLine(const char *text)
{
	const auto *p = reinterpret_cast<const unsigned char *>(text);
	while (*p) {
		if (*p < 0x20 || *p == 0x7f)
			return false;
		int more = *p < 0x80 ? 0 : (*p & 0xe0) == 0xc0 && *p >= 0xc2 ? 1 : (*p & 0xf0) == 0xe0 ? 2
			 : (*p & 0xf8) == 0xf0 && *p <= 0xf4 ? 3 : -1;
		if (more < 0)
			return false;
		for (p++; more > 0; more--, p++)
			if ((*p & 0xc0) != 0x80)
				return false;
	}
	return *text != '\0';
}

// The same, and it names the file.
inline bool namesFile(const char *text, const char *name)
{
	return printableLine(text) && std::strstr(text, name) != nullptr;
}

// Stops the run with the broken rule and the message, so the report says what was wrong.
[[noreturn]] inline void fail(const char *rule, const char *message)
{
	std::fprintf(stderr, "fuzz check failed: %s\nmessage: %s\n", rule, message);
	std::abort();
}

} // namespace calped::fuzz
