// SPDX-License-Identifier: BSD-2-Clause
// Command-line options shared by the live examples (calped-aravis, calped-play,
// calped-libcamera): detector setup, outputs and when to stop. Each example adds its
// source's own options through the same splitter.
#pragma once

#include <string>
#include <vector>

namespace calped {
namespace live {

struct LiveOptions {
	std::string model;         // --model BLOB (required)
	std::string calibPath;     // --calib FILE
	bool calibrated = false;   // --method calibrated
	double resize = 1.0;       // --resize R
	bool resizeInPyramid = false; // --resize-in-pyramid
	bool calibratedPyramid = false; // --calibrated-pyramid
	bool rejectStatic = false;    // --reject-static
	double minHeight = 1.4;    // --min-height H, metres
	double maxHeight = 2.2;    // --max-height H, metres
	std::string overlayDir;    // --overlay DIR
	int overlayEvery = 1;      // --overlay-every K
	long frames = 0;           // --frames N: stop after N processed frames (0: until stopped)
	double statsEvery = 5.0;   // --stats-every S: seconds between stats lines on stderr
	int timeoutMs = 2000;      // --timeout MS: wait per frame before counting a timeout
	bool quiet = false;        // --quiet: no stats lines
	bool help = false;
};

// One command-line option: "--name VALUE", "--name=VALUE" or a flag "--name".
struct Arg {
	std::string name;
	std::string value;
	bool hasValue = false;
};

// Splits argv into options. `flags` lists the example's options without a value,
// `valued` those with one (the common options are added to both); anything else is an
// unknown option, and positional arguments are refused.
bool splitArgs(int argc, const char *const *argv, const std::vector<std::string> &flags,
	       const std::vector<std::string> &valued, std::vector<Arg> &out, std::string &error);
// The first form (kept for examples written against it): every option not in `flags`
// takes a value, and the caller reports unknown names.
bool splitArgs(int argc, const char *const *argv, const std::vector<std::string> &flags,
	       std::vector<Arg> &out, std::string &error);

enum class ParseResult { NotMine, Ok, Error };

// Consumes one of the common options; NotMine lets the example try its own.
ParseResult parseLiveOption(const Arg &arg, LiveOptions &out, std::string &error);

// Cross-option checks after every option was parsed (e.g. --model given).
bool checkLiveOptions(const LiveOptions &options, std::string &error);

// The common options' part of --help.
const char *liveUsageText();

// Number parsing for the examples' own options: the whole text must be the number.
bool parseNumber(const std::string &text, double &out);
bool parseWhole(const std::string &text, long &out);

} // namespace live
} // namespace calped
