// SPDX-License-Identifier: BSD-2-Clause
// Runs a program as a black box and captures what it did.
#pragma once

#include <string>
#include <vector>

namespace calped::test {

struct ProcessResult {
	bool exited = false;   // false: killed by a signal (a crash, for our purposes)
	int exitCode = -1;
	int signal = 0;
	std::string out;       // standard output
	std::string err;       // standard error
};

// Runs `program` with `args` (argv[1..]), standard input from /dev/null. Output goes
// through files in `scratchDir`, so large outputs cannot deadlock a pipe.
ProcessResult runProcess(const std::string &program, const std::vector<std::string> &args,
			 const std::string &scratchDir);

// Lines of `text` without their '\n' (a final line without '\n' still counts).
std::vector<std::string> splitLines(const std::string &text);

std::string readTextFile(const std::string &path);

} // namespace calped::test
