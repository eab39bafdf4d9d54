// SPDX-License-Identifier: BSD-2-Clause
// One-line error reporting shared by the command-line tools and the examples.
#pragma once

#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include <calped/status.h>

namespace calped::apps {

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

// A Status message without its "ErrorCode: " prefix, for one-line errors.
inline std::string statusText(const Status &st)
{
	const char *text = st.message();
	const char *code = errorCodeName(st.code());
	const size_t n = std::strlen(code);
	return std::strncmp(text, code, n) == 0 && text[n] == ':' && text[n + 1] == ' ' ? text + n + 2
											: text;
}

// Runs body() and turns an exception escaping it (out of memory, an internal error) into
// one error line and kExitRuntime: the programs' last line of defence, never a crash.
template <typename Body>
int runGuarded(const char *program, Body body)
{
	try {
		return body();
	} catch (const std::bad_alloc &) {
		return cliFail(program, kExitRuntime, "out of memory");
	} catch (const std::exception &e) {
		return cliFail(program, kExitRuntime, std::string("internal error: ") + e.what());
	}
}

} // namespace calped::apps
