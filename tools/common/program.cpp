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

int parseCommandLine(const ProgramInfo &program, const std::vector<OptionSpec> &table,
		     bool allowPositional, int argc, const char *const *argv, ParsedArgs &out,
		     const OptionTaker &take)
{
	const int rc = parseCommandLine(program, table, allowPositional, argc, argv, out);
	if (rc >= 0)
		return rc;
	std::vector<ParsedOption> rest;
	std::string error;
	for (ParsedOption &o : out.options) {
		if (!take(o, error))
			rest.push_back(std::move(o));
		else if (!error.empty())
			return usageError(program, error);
	}
	out.options = std::move(rest);
	return -1;
}

std::vector<OptionSpec> joinOptions(std::vector<OptionSpec> table, const std::vector<OptionSpec> &more)
{
	table.insert(table.end(), more.begin(), more.end());
	return table;
}

} // namespace calped::apps
