// SPDX-License-Identifier: BSD-2-Clause
// One-line error reporting shared by the command-line tools (calped-detect, calped-eval).
#pragma once

#include <cstdio>
#include <string>

namespace calped {

constexpr int kExitRuntime = 1;
constexpr int kExitUsage = 2;

// Prints "PROGRAM: MESSAGE" as one line on stderr (line breaks become spaces, so each error
// is one line in a log) and returns code, for `return cliFail(...)`.
inline int cliFail(const char *program, int code, std::string message)
{
	for (char &c : message)
		if (c == '\n' || c == '\r')
			c = ' ';
	std::fprintf(stderr, "%s: %s\n", program, message.c_str());
	return code;
}

} // namespace calped
