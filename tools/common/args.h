// SPDX-License-Identifier: BSD-2-Clause
// The one command-line parser of the programs (getopt_long underneath). Each program
// declares its options in a table (long name, value or not, help text); the parser accepts
// "--opt value", "--opt=value", an unambiguous prefix of a long name, "--" to end the
// options, and handles -h/--help and --version itself. Usage errors are one line naming the
// flag as the user wrote it; the program prefixes its name and exits kExitUsage (2).
#pragma once

#include <string>
#include <vector>

namespace calped::apps {

struct OptionSpec {
	const char *name;      // long name without "--", e.g. "resize"; nullptr: a heading in
			       // --help (`help` is its text), not an option
	const char *valueName; // "R" for "--resize R"; nullptr for a flag without a value
	const char *help;      // one or more lines ('\n' between them) for --help
	char shortName = 0;    // e.g. 'o' for "-o FILE"; 0 for none
};

struct ParsedOption {
	std::string name;    // the table's long name ("resize"), whatever prefix was typed
	std::string flag;    // as written, for messages: "--resize", "--res" or "-o"
	std::string value;   // empty for a flag
};

struct ParsedArgs {
	std::vector<ParsedOption> options; // in command-line order
	std::vector<std::string> positional;
	bool help = false;
	bool version = false;
};

// Splits argv by `table` (plus -h/--help and --version). Positional arguments may come
// anywhere; `allowPositional` false refuses them. False with a one-line `error` (without
// the program prefix) on a usage error.
bool parseArgs(int argc, const char *const *argv, const std::vector<OptionSpec> &table,
	       bool allowPositional, ParsedArgs &out, std::string &error);

// The options part of --help, generated from the table ("  --resize R   help"), with
// -h/--help and --version at the end when `withStandard`.
std::string optionsHelp(const std::vector<OptionSpec> &table, bool withStandard = true);

// Whole-string, finite number parsing (shared by every program: "2x", "", "nan" fail).
bool parseNumber(const std::string &text, double &out);
bool parseWhole(const std::string &text, long &out);

// "768x576" with both sides from 1 to 16384 (video and camera frame sizes).
bool parseFrameSize(const std::string &text, int &width, int &height);

// "--resize: expected a number > 0 and <= 8, got 'x'"
std::string badValue(const ParsedOption &option, const std::string &expected);

// Value checks that fill `error` with badValue() when they fail.
bool numberIn(const ParsedOption &option, double lo, bool loOpen, double hi, double &out,
	      std::string &error);
bool wholeIn(const ParsedOption &option, long lo, long hi, long &out, std::string &error);
bool nonEmpty(const ParsedOption &option, const char *what, std::string &out, std::string &error);

} // namespace calped::apps
