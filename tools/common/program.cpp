// SPDX-License-Identifier: BSD-2-Clause
#include "program.h"

#include <cstdio>

#include <calped/version.h>

#include "cli_error.h"

namespace calped::apps {

std::string versionLine(const char *program)
{
	return std::string(program) + " " + CALPED_VERSION;
}

void printHelp(const ProgramInfo &program, const std::vector<OptionSpec> &table)
{
	std::fputs(program.synopsis, stdout);
	std::fputs(optionsHelp(table).c_str(), stdout);
	std::fputs(program.epilogue, stdout);
}

int usageError(const ProgramInfo &program, const std::string &message)
{
	return cliFail(program.name, kExitUsage, message);
}

int parseCommandLine(const ProgramInfo &program, const std::vector<OptionSpec> &table,
		     bool allowPositional, int argc, const char *const *argv, ParsedArgs &out)
{
	std::string error;
	if (!parseArgs(argc, argv, table, allowPositional, out, error))
		return usageError(program, error);
	if (out.help) {
		printHelp(program, table);
		return 0;
	}
	if (out.version) {
		std::printf("%s\n", versionLine(program.name).c_str());
		return 0;
	}
	return -1;
}

} // namespace calped::apps
