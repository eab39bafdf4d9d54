// SPDX-License-Identifier: BSD-2-Clause
// calped-eval: the detector over a sequence against ground truth, for every (method, resize),
// with the thesis-style table, JSON, detection CSVs, plots and overlays. docs/evaluation.md.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include <calped/calped.h>

#include "cli_error.h"
#include "file_io.h"
#include "frame_list.h"
#include "writers.h"
#include "dets_csv.h"
#include "eval_options.h"
#include "frame_source.h"
#include "ground_truth.h"
#include "markdown_report.h"
#include "stop_signal.h"
#include "methods.h"
#include "metrics.h"
#include "overlay_frames.h"
#include "plots.h"
#include "report.h"
#include "run.h"
#include "runner.h"
#include "text_fields.h"

using calped::apps::cliFail;
using calped::apps::kExitRuntime;
using calped::apps::kExitUsage;

namespace calped::eval_tool {

namespace {

int fail(int code, std::string message)
{
	return cliFail("calped-eval", code, std::move(message));
}

void notice(const EvalOptions &opt, const std::string &message)
{
	if (!opt.quiet)
		std::fprintf(stderr, "calped-eval: %s\n", message.c_str());
}

bool makeOutputDirs(const EvalOptions &opt, std::string &error)
{
	for (const std::string *dir : { &opt.detsDir, &opt.plotsDir, &opt.overlayDir, &opt.framesJsonlDir })
		if (!dir->empty() && !apps::makeDirectories(*dir, error))
			return false;
	return true;
}

// "generic_r2.0" -> method "generic", resize 2.0; other names keep resize 0 (unknown).
void splitStem(const std::string &stem, std::string &method, double &resize)
{
	method = stem;
	resize = 0;
	const size_t r = stem.rfind("_r");
	double v;
	if (r != std::string::npos && r > 0 && parseDouble(stem.substr(r + 2), v) && v > 0) {
		method = stem.substr(0, r);
		resize = v;
	}
}

// Everything after the runs: stdout tables, then the files, plots last (slowest, optional).
int writeOutputs(const EvalOptions &opt, const std::vector<RunResult> &runs,
		 const std::string &framesText, bool ran)
{
	std::string error;
	std::fputs(accuracyTable(runs).c_str(), stdout);
	const std::string stages = stageTable(runs);
	if (!stages.empty())
		std::fputs(("\n" + stages).c_str(), stdout);
	std::fflush(stdout);

	if (!opt.jsonPath.empty() && !writeTextFile(opt.jsonPath, runsJson(runs), error))
		return fail(kExitRuntime, error);
	if (ran && !opt.detsDir.empty()) {
		for (const RunResult &r : runs)
			if (!writeDetectionsCsv(opt.detsDir + "/" + runStem(r.method, r.resize) + ".csv",
						r.detections, error))
				return fail(kExitRuntime, error);
	}

	MarkdownContext md;
	md.groundTruth = opt.gt;
	md.frames = framesText;
	md.overlayScore = opt.overlayScore;
	if (ran && !opt.overlayDir.empty()) {
		for (const RunResult &r : runs)
			for (long f : opt.overlayFrames)
				if (f <= r.frames)
					md.overlays.push_back(opt.overlayDir + "/" + runStem(r.method, r.resize) + "/" +
							      apps::overlayFileName(f));
	}
	int rc = 0;
	if (!opt.plotsDir.empty() && !runs.empty()) {
		std::string skipped;
		if (!writePlots(opt.plotsDir, runs, md.plots, skipped, error))
			rc = fail(kExitRuntime, error); // still write the page, without the plots
		else if (!skipped.empty())
			notice(opt, skipped);
	}
	if (!opt.markdownPath.empty() &&
	    !writeTextFile(opt.markdownPath, markdownReport(opt.markdownPath, runs, md), error))
		return fail(kExitRuntime, error);
	return rc;
}

int scoreOnly(const EvalOptions &opt, const GroundTruth &truth)
{
	std::string error;
	// The frames the CSVs cover (a row beyond them is an error), and the first of them
	// that are scored (--max-frames: later rows are left out).
	long covered = opt.numFrames;
	if (!opt.framesDir.empty()) {
		std::vector<std::string> files;
		if (!apps::listFrames({ opt.framesDir }, files, error))
			return fail(kExitRuntime, error);
		covered = static_cast<long>(files.size());
	}
	const long frames = opt.maxFrames > 0 ? std::min(covered, opt.maxFrames) : covered;
	std::string framesText = std::to_string(frames) + " frames";
	if (!opt.framesDir.empty())
		framesText = "`" + opt.framesDir + "` (" + std::to_string(frames) + " frames)";
	if (!makeOutputDirs(opt, error))
		return fail(kExitRuntime, error);
	std::vector<RunResult> runs;
	for (const std::string &path : opt.scoreOnly) {
		RunResult r;
		if (!readDetectionsCsv(path, covered, r.detections, error))
			return fail(kExitRuntime, error);
		r.detections.resize(size_t(frames));
		splitStem(std::filesystem::path(path).stem().string(), r.method, r.resize);
		if (!opt.label.empty())
			r.method = opt.label;
		r.frames = frames;
		r.evaluation = evaluateSequence(truth, r.detections, frames);
		runs.push_back(std::move(r));
	}
	return writeOutputs(opt, runs, framesText, false);
}

int run(const EvalOptions &opt)
{
	std::string error;
	GroundTruth truth;
	if (!loadGroundTruth(opt.gt, truth, error))
		return fail(kExitRuntime, error);
	if (!opt.scoreOnly.empty())
		return scoreOnly(opt, truth);

	// Methods first: when every one is skipped there is nothing to load.
	std::vector<RunSpec> specs;
	std::vector<const MethodEntry *> methods;
	for (const std::string &name : opt.methods) {
		const MethodEntry *m = findMethod(name);
		if (std::find(methods.begin(), methods.end(), m) != methods.end())
			continue;
		if (m->needsCalibration && opt.calib.empty()) {
			notice(opt, std::string("method '") + m->name + "' needs --calib FILE; skipped");
			continue;
		}
		methods.push_back(m);
	}
	for (double resize : opt.resizes)
		for (const MethodEntry *m : methods)
			specs.push_back({ m, resize });
	if (specs.empty()) {
		notice(opt, "no available method to run; nothing to do");
		return 0;
	}

	FrameInput input;
	const bool resolved = opt.video.empty()
				      ? resolveFolderInput(opt.framesDir, opt.maxFrames, input, error)
				      : resolveVideoInput(opt.video, opt.videoSize, opt.maxFrames, input, error);
	if (!resolved)
		return fail(kExitRuntime, error);

	Model model;
	if (!apps::loadModelFile(opt.model, model, error))
		return fail(kExitRuntime, error);
	if (!makeOutputDirs(opt, error))
		return fail(kExitRuntime, error);

	RunSettings settings;
	settings.input = &input;
	settings.model = &model;
	settings.options = opt.detector;
	settings.framesJsonlDir = opt.framesJsonlDir;
	settings.truth = &truth;
	settings.overlayDir = opt.overlayDir;
	settings.overlayFrames = opt.overlayFrames;
	settings.overlayScore = opt.overlayScore;
	settings.quiet = opt.quiet;
	notice(opt, std::to_string(specs.size()) + " run(s), " +
			    (input.isVideo() ? "video " + input.video
					     : std::to_string(input.files.size()) + " frames from " + opt.framesDir) +
			    (opt.jobs > 1 ? ", " + std::to_string(opt.jobs) + " at a time" : ""));

	std::vector<RunResult> runs;
	if (!runAll(specs, settings, opt.jobs, runs, error)) {
		if (calped::apps::stopRequested())
			return calped::apps::stopExitCode(); // no scores from a partial run
		return fail(kExitRuntime, error);
	}

	const long frames = runs.front().frames;
	for (RunResult &r : runs) {
		// Every run reads the same input; a video that decodes differently is an error.
		if (r.frames != frames)
			return fail(kExitRuntime, runStem(r.method, r.resize) + " processed " +
							  std::to_string(r.frames) + " frames but " +
							  runStem(runs.front().method, runs.front().resize) +
							  " processed " + std::to_string(frames));
		r.evaluation = evaluateSequence(truth, r.detections, frames);
		const RunCounters &c = r.counters;
		if (c.droppedWindows)
			notice(opt, "warning: " + runStem(r.method, r.resize) + " dropped " +
					    std::to_string(c.droppedWindows) +
					    " windows over the candidate capacity");
		if (c.tooSmall)
			notice(opt, "warning: " + runStem(r.method, r.resize) + ": " +
					    std::to_string(c.tooSmall) +
					    " frames smaller than the model window (no detections)");
	}
	if (truth.lastFrame() > frames)
		notice(opt, "scored frames 1-" + std::to_string(frames) + "; the ground truth goes on to frame " +
				    std::to_string(truth.lastFrame()) + " (" +
				    std::to_string(truth.count(truth.lastFrame(), false) -
						   truth.count(frames, false)) +
				    " boxes not counted)");
	const std::string framesText = "`" + (input.isVideo() ? input.video : opt.framesDir) + "` (" +
				       std::to_string(frames) + " frames)";
	return writeOutputs(opt, runs, framesText, true);
}

} // namespace

} // namespace calped::eval_tool

int main(int argc, char **argv)
{
	using namespace calped::eval_tool;

	// SIGINT/SIGTERM: each run finishes its frame, exit 128 + the signal; a closed pipe
	// becomes a reported write error.
	calped::apps::installStopHandlers();
	EvalOptions opt;
	std::string error;
	if (!parseEvalOptions(argc, argv, opt, error))
		return fail(kExitUsage, error);
	if (opt.help) {
		calped::apps::printHelp(kEvalProgram, evalOptionTable());
		return 0;
	}
	if (opt.version) {
		std::printf("%s\n", calped::apps::versionLine(kEvalProgram.name).c_str());
		return 0;
	}
	return calped::apps::runGuarded("calped-eval", [&] { return run(opt); });
}
