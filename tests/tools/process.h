// SPDX-License-Identifier: BSD-2-Clause
// Runs a program as a black box and captures what it did.
#pragma once

#include <string>
#include <vector>

namespace calped::test {

struct ProcessResult {
	bool exited = false;   // false: killed by a signal (a crash, for our purposes)
	bool hung = false;     // still running at waitProcess's deadline (then killed)
	int exitCode = -1;
	int signal = 0;
	std::string out;       // standard output
	std::string err;       // standard error
};

// Runs `program` with `args` (argv[1..]), standard input from /dev/null. Output goes
// through files in `scratchDir`, so large outputs cannot deadlock a pipe.
ProcessResult runProcess(const std::string &program, const std::vector<std::string> &args,
			 const std::string &scratchDir);

// A program started by startProcess, to signal while it runs.
struct RunningProcess {
	int pid = -1;
	std::string outPath, errPath;
};

// Starts `program` as runProcess does and returns at once.
RunningProcess startProcess(const std::string &program, const std::vector<std::string> &args,
			    const std::string &scratchDir);

// Waits for it to end, at most timeoutSeconds; past that it is killed (SIGKILL) and the
// result says hung.
ProcessResult waitProcess(RunningProcess &process, double timeoutSeconds);

// Lines of `text` without their '\n' (a final line without '\n' still counts).
std::vector<std::string> splitLines(const std::string &text);

std::string readTextFile(const std::string &path);

} // namespace calped::test
