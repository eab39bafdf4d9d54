// SPDX-License-Identifier: BSD-2-Clause
// Checks shared by the fuzz targets.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace calped::fuzz {

// An error message for people and logs: one line, no control characters (a field quoted
// from the input must not carry a newline or a terminal escape into it), not empty.
inline bool printableLine(const char *text)
{
	for (const char *p = text; *p; p++)
		if (static_cast<unsigned char>(*p) < 0x20 || *p == 0x7f)
			return false;
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
