// SPDX-License-Identifier: BSD-2-Clause
// Command-line options of calped-eval (docs/evaluation.md).
#pragma once

#include <string>
#include <vector>

namespace calped::eval_tool {

struct EvalOptions {
	std::string framesDir;
	std::string video;
	std::string videoSize; // "WxH" or empty (ffprobe)
	std::string gt;
	std::string model;
	std::string calib;
	std::vector<std::string> methods{ "generic" };
	std::vector<double> resizes{ 1.0 };
	std::string jsonPath;
	std::string detsDir;
	std::string plotsDir;
	std::string overlayDir;
	std::string markdownPath;
	std::vector<long> overlayFrames{ 1, 200, 400, 600 };
	double overlayScore = 30.0;
	long maxFrames = 0;
	long numFrames = 0; // --score-only without --frames
	int jobs = 1;
	std::vector<std::string> scoreOnly; // detection CSVs to score instead of running
	std::string label;                  // method name for a single --score-only file
	bool resizeInPyramid = false; // DetectorConfig::resizeInPyramid for every run
	bool calibratedPyramid = false; // DetectorConfig::calibratedPyramid, calibrated runs
	bool quiet = false;
	bool help = false;
};

// On a usage error returns false with a one-line `error` (no program-name prefix).
bool parseEvalOptions(int argc, const char *const *argv, EvalOptions &out, std::string &error);

const char *evalUsageText();

} // namespace calped::eval_tool
