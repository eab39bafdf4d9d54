// SPDX-License-Identifier: BSD-2-Clause
// What every program does with its command line before its own work: parse it by its
// option table, answer -h/--help and --version, and turn a usage error into one line on
// standard error and exit status kExitUsage.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "args.h"

namespace calped::apps {

struct ProgramInfo {
	const char *name;     // "calped-detect": error prefix and --version
	const char *synopsis; // help text before the options ("usage: ...\n\n...\n")
	const char *epilogue; // help text after the options (may be "")
};

// -1: go on with `out`; otherwise the exit status to return at once (0 after --help or
// --version, kExitUsage after a usage error, which is printed).
int parseCommandLine(const ProgramInfo &program, const std::vector<OptionSpec> &table,
		     bool allowPositional, int argc, const char *const *argv, ParsedArgs &out);

// The same, then offers each option to `take` first (e.g. takeDetectorOption): those it
// consumes (returns true) leave out.options, a non-empty error from it is a usage error.
using OptionTaker = std::function<bool(const ParsedOption &option, std::string &error)>;
int parseCommandLine(const ProgramInfo &program, const std::vector<OptionSpec> &table,
		     bool allowPositional, int argc, const char *const *argv, ParsedArgs &out,
		     const OptionTaker &take);

// `table` with `more` appended (a program's own options and the shared ones).
std::vector<OptionSpec> joinOptions(std::vector<OptionSpec> table, const std::vector<OptionSpec> &more);

// "calped-detect 0.1.0"
std::string versionLine(const char *program);

// Prints the whole --help text to standard output.
void printHelp(const ProgramInfo &program, const std::vector<OptionSpec> &table);

// A usage error found after parsing: "PROGRAM: message" on stderr, returns kExitUsage.
int usageError(const ProgramInfo &program, const std::string &message);

} // namespace calped::apps
