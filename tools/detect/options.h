// SPDX-License-Identifier: BSD-2-Clause
// Command-line options of calped-detect.
#pragma once

#include <string>
#include <vector>

namespace calped::detect_tool {

struct Options {
	std::string model;
	double resize = 1.0;
	std::string csvPath;
	std::string jsonlPath; // "-" means standard output
	std::string overlayDir;
	int overlayEvery = 1;
	long maxFrames = 0; // 0 means every frame
	bool noNms = false;
	bool noBoxVoting = false;
	bool resizeInPyramid = false;
	bool calibratedPyramid = false;
	bool rejectStatic = false;
	std::string calibPath;         // calibration file (any format calibration.h reads)
	bool calibrated = false;       // --method calibrated
	double minHeight = 1.4;        // plausible person heights, metres
	double maxHeight = 2.2;
	bool quiet = false;
	bool help = false;
	std::vector<std::string> inputs;
};

// Parses argv into `out`. On a usage error returns false and sets `error` to one line
// (without the program-name prefix).
bool parseOptions(int argc, const char *const *argv, Options &out, std::string &error);

// The --help text.
const char *usageText();

} // namespace calped::detect_tool
