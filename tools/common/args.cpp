// SPDX-License-Identifier: BSD-2-Clause
#include "args.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <algorithm>
#include <cstring>
#include <getopt.h>

namespace calped::apps {

namespace {

constexpr int kHelp = 1000;
constexpr int kVersion = 1001;
constexpr int kFirst = 2000; // getopt's val for table entry i is kFirst + i

// The flag as typed: "--res=2" -> "--res".
std::string spelled(const char *arg)
{
	const char *eq = std::strchr(arg, '=');
	return eq && arg[0] == '-' && arg[1] == '-' ? std::string(arg, eq) : std::string(arg);
}

// For an unknown "--xy": the long names it is a prefix of (getopt reports ambiguity as
// unknown).
std::string candidates(const std::string &flag, const std::vector<OptionSpec> &table)
{
	if (flag.size() < 3 || flag.compare(0, 2, "--") != 0)
		return "";
	const std::string stem = flag.substr(2);
	std::string names;
	int n = 0;
	for (const OptionSpec &s : table)
		if (s.name && std::strncmp(s.name, stem.c_str(), stem.size()) == 0) {
			names += std::string(n++ ? ", --" : "--") + s.name;
		}
	return n > 1 ? names : "";
}

} // namespace

bool parseArgs(int argc, const char *const *argv, const std::vector<OptionSpec> &table,
	       bool allowPositional, ParsedArgs &out, std::string &error)
{
	out = ParsedArgs();
	std::vector<struct option> longs;
	// '-': arguments that are not options come back in order as 1 (whatever POSIXLY_CORRECT
	// says); ':': a missing value is reported as ':'.
	std::string shorts = "-:h";
	for (size_t i = 0; i < table.size(); i++) {
		if (!table[i].name)
			continue; // a heading
		const bool valued = table[i].valueName != nullptr;
		longs.push_back({ table[i].name, valued ? required_argument : no_argument, nullptr,
				  kFirst + static_cast<int>(i) });
		if (table[i].shortName) {
			shorts += table[i].shortName;
			if (valued)
				shorts += ':';
		}
	}
	longs.push_back({ "help", no_argument, nullptr, kHelp });
	longs.push_back({ "version", no_argument, nullptr, kVersion });
	longs.push_back({ nullptr, 0, nullptr, 0 });

	// getopt permutes the argument pointers: it works on a copy of the array.
	std::vector<char *> args;
	for (int i = 0; i < argc; i++)
		args.push_back(const_cast<char *>(argv[i]));
	args.push_back(nullptr);
	optind = 0; // glibc: a full reset, so the parser can run more than once
	opterr = 0;
	for (;;) {
		optarg = nullptr;
		const int c = getopt_long(argc, args.data(), shorts.c_str(), longs.data(), nullptr);
		if (c == -1)
			break;
		if (c == 1) {
			out.positional.push_back(optarg);
			continue;
		}
		// The option just read is argv[optind - 1], or argv[optind - 2] when its value
		// was the next argument.
		const int at = optarg && optind >= 2 && optarg == args[optind - 1] ? optind - 2
										   : optind - 1;
		const std::string flag = at >= 1 && at < argc && args[at] ? spelled(args[at])
									  : std::string();
		if (c == '?') {
			if (optopt >= kFirst || optopt == kHelp || optopt == kVersion) {
				error = flag + " takes no value";
			} else if (optopt != 0) {
				error = "unknown option '-" + std::string(1, static_cast<char>(optopt)) +
					"' (try --help)";
			} else {
				const std::string alt = candidates(flag, table);
				error = alt.empty() ? "unknown option '" + flag + "' (try --help)"
						    : "ambiguous option '" + flag + "' (could be " + alt + ")";
			}
			return false;
		}
		if (c == ':') {
			error = flag + " needs a value";
			for (size_t i = 0; i < table.size(); i++)
				if (table[i].name && (optopt == kFirst + static_cast<int>(i) ||
						      (table[i].shortName && optopt == table[i].shortName)))
					error = flag + " needs a value (" + table[i].valueName + ")";
			return false;
		}
		if (c == 'h' || c == kHelp) {
			out.help = true;
			continue;
		}
		if (c == kVersion) {
			out.version = true;
			continue;
		}
		const OptionSpec *spec = nullptr;
		for (size_t i = 0; i < table.size() && !spec; i++)
			if (table[i].name && (c == kFirst + static_cast<int>(i) || (table[i].shortName && c == table[i].shortName)))
				spec = &table[i];
		if (!spec) {
			error = "unknown option '" + flag + "' (try --help)";
			return false;
		}
		ParsedOption o;
		o.name = spec->name;
		o.flag = flag;
		if (spec->valueName)
			o.value = optarg ? optarg : "";
		out.options.push_back(o);
	}
	for (int i = optind; i < argc; i++)
		out.positional.push_back(args[i]);
	if (!allowPositional && !out.positional.empty() && !out.help && !out.version) {
		error = "unexpected argument '" + out.positional.front() + "' (try --help)";
		return false;
	}
	return true;
}

std::string optionsHelp(const std::vector<OptionSpec> &table, bool withStandard)
{
	std::vector<std::pair<std::string, std::string>> rows; // left "" + text: a heading
	for (const OptionSpec &s : table) {
		if (!s.name) {
			rows.push_back({ "", s.help });
			continue;
		}
		std::string left = "  ";
		if (s.shortName)
			left += std::string("-") + s.shortName + ", ";
		left += std::string("--") + s.name;
		if (s.valueName)
			left += std::string(" ") + s.valueName;
		rows.push_back({ left, s.help });
	}
	if (withStandard) {
		rows.push_back({ "  -h, --help", "show this help" });
		rows.push_back({ "  --version", "print the program's name and version" });
	}
	size_t width = 0;
	for (const auto &r : rows)
		width = std::max(width, r.first.size());
	width = std::min<size_t>(width + 2, 26);
	std::string text;
	for (const auto &r : rows) {
		if (r.first.empty()) {
			text += (text.empty() ? "" : "\n") + r.second + "\n";
			continue;
		}
		std::string left = r.first;
		if (left.size() + 2 > width) {
			text += left + "\n";
			left.clear();
		}
		size_t pos = 0;
		do {
			const size_t nl = r.second.find('\n', pos);
			const std::string line = r.second.substr(pos, nl == std::string::npos ? nl : nl - pos);
			text += left + std::string(width - left.size(), ' ') + line + "\n";
			left.clear();
			pos = nl == std::string::npos ? nl : nl + 1;
		} while (pos != std::string::npos);
	}
	return text;
}

namespace {

// strtod and strtol skip leading space: "whole string" means none either.
bool startsWithSpace(const std::string &text)
{
	return !text.empty() && std::isspace(static_cast<unsigned char>(text[0]));
}

} // namespace

bool parseNumber(const std::string &text, double &out)
{
	if (text.empty() || startsWithSpace(text))
		return false;
	// Decimal only: strtod also reads hexadecimal ("0x2" would be 2), "inf" and "nan".
	for (char c : text)
		if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != 'e' && c != 'E' &&
		    c != '+' && c != '-')
			return false;
	errno = 0;
	char *end = nullptr;
	const double v = std::strtod(text.c_str(), &end);
	if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v))
		return false;
	out = v;
	return true;
}

bool parseWhole(const std::string &text, long &out)
{
	if (text.empty() || startsWithSpace(text))
		return false;
	errno = 0;
	char *end = nullptr;
	const long v = std::strtol(text.c_str(), &end, 10);
	if (errno != 0 || end != text.c_str() + text.size())
		return false;
	out = v;
	return true;
}

bool parseFrameSize(const std::string &text, int &width, int &height)
{
	const size_t x = text.find('x');
	long w = 0, h = 0;
	if (x == std::string::npos || !parseWhole(text.substr(0, x), w) || !parseWhole(text.substr(x + 1), h))
		return false;
	if (w < 1 || h < 1 || w > 16384 || h > 16384)
		return false;
	width = static_cast<int>(w);
	height = static_cast<int>(h);
	return true;
}

std::string badValue(const ParsedOption &option, const std::string &expected)
{
	return option.flag + ": expected " + expected + ", got '" + option.value + "'";
}

namespace {

std::string numberText(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%g", v);
	return buf;
}

} // namespace

bool numberIn(const ParsedOption &option, double lo, bool loOpen, double hi, double &out,
	      std::string &error)
{
	double v = 0;
	if (!parseNumber(option.value, v) || (loOpen ? !(v > lo) : !(v >= lo)) || v > hi) {
		error = badValue(option, "a number " + std::string(loOpen ? "> " : ">= ") +
						 numberText(lo) + " and <= " + numberText(hi));
		return false;
	}
	out = v;
	return true;
}

bool wholeIn(const ParsedOption &option, long lo, long hi, long &out, std::string &error)
{
	long v = 0;
	if (!parseWhole(option.value, v) || v < lo || v > hi) {
		error = badValue(option, "a whole number from " + std::to_string(lo) + " to " +
						 std::to_string(hi));
		return false;
	}
	out = v;
	return true;
}

bool nonEmpty(const ParsedOption &option, const char *what, std::string &out, std::string &error)
{
	if (option.value.empty()) {
		error = badValue(option, what);
		return false;
	}
	out = option.value;
	return true;
}

} // namespace calped::apps
