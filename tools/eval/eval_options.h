// SPDX-License-Identifier: BSD-2-Clause
// Command-line options of calped-eval (docs/evaluation.md).
#pragma once

#include <string>
#include <vector>

#include "args.h"
#include "detector_options.h"
#include "program.h"

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
	std::string framesJsonlDir; // DIR/<method>_r<resize>.jsonl: the JSON frame records
	// --resize-at and --levels (with --model and --calib, copied into model and calib):
	// each run's DetectorOptions start from these, then take its method and resize.
	apps::DetectorOptions detector;
	bool quiet = false;
	bool help = false;
	bool version = false;
};

// On a usage error returns false with a one-line `error` (no program-name prefix).
bool parseEvalOptions(int argc, const char *const *argv, EvalOptions &out, std::string &error);

// The table --help is generated from, and the text around it.
const std::vector<apps::OptionSpec> &evalOptionTable();
extern const apps::ProgramInfo kEvalProgram;

} // namespace calped::eval_tool
