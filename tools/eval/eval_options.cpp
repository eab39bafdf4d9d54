// SPDX-License-Identifier: BSD-2-Clause
#include "eval_options.h"

#include <algorithm>

#include "methods.h"
#include "text_fields.h"

namespace calped::eval_tool {

namespace {

std::vector<std::string> splitList(const std::string &text)
{
	std::vector<std::string> items;
	for (const std::string &s : splitCsvLine(text))
		if (!s.empty())
			items.push_back(s);
	return items;
}

} // namespace

const apps::ProgramInfo kEvalProgram = {
	"calped-eval",
	"usage: calped-eval (--frames DIR | --video FILE [--size WxH]) --gt FILE --model BLOB\n"
	"                   [--calib FILE] [--methods generic[,calibrated]] [--resizes 1.5,2.0,2.5]\n"
	"                   [--resize-at pyramid|frame] [--levels placed|toolbox] [options]\n"
	"       calped-eval --score-only DETS.csv[,DETS.csv...] --gt FILE\n"
	"                   (--frames DIR | --num-frames N) [--label NAME] [--json FILE] [--plots DIR]\n"
	"\n"
	"Runs the detector over a frame sequence against ground truth (CVML XML or MOTChallenge\n"
	"gt.txt) and prints the thesis-style table: scales (octaves), classifier applications per\n"
	"frame, TPR and FPPF (greedy matching at IoU >= 0.5), the thesis's any-overlap TPR, the\n"
	"log-average miss rate, detector time and peak memory. See docs/evaluation.md.\n"
	"\n"
	"options:\n",
	"\n"
	"exit status: 0 success, 1 runtime error, 2 usage error\n",
};

const std::vector<apps::OptionSpec> &evalOptionTable()
{
	static const std::vector<apps::OptionSpec> table = [] {
		std::vector<apps::OptionSpec> t = {
			{ "frames", "DIR", "images of the sequence, sorted by name; frame k is the k-th" },
			{ "video", "FILE", "a video decoded through an ffmpeg pipe (needs ffmpeg)" },
			{ "size", "WxH", "the video's frame size (default: asked from ffprobe)" },
			{ "gt", "FILE", "ground truth: CVML XML (frames 0-based) or MOTChallenge gt.txt" },
			{ "methods", "LIST", "generic, calibrated, calibrated-static (default generic);\n"
					     "the calibrated ones need --calib and are skipped with a\n"
					     "notice without it" },
			{ "resizes", "LIST", "input resizes (default 1.0)" },
		};
		return apps::joinOptions(apps::joinOptions(t, apps::detectorOptionTable(apps::DetectorFlags::Eval)), {
			{ "json", "FILE", "one JSON object per (method, resize)" },
			{ "dets", "DIR", "DIR/<method>_r<resize>.csv: frame,x,y,w,h,score" },
			{ "frames-jsonl", "DIR", "DIR/<method>_r<resize>.jsonl: calped-detect's JSON frame\n"
						 "records, one per frame" },
			{ "plots", "DIR", "TPR-vs-FPPF and stage-time PNG plots (needs gnuplot)" },
			{ "overlays", "DIR", "DIR/<method>_r<resize>/NNNNNN.png: frames with ground\n"
					     "truth (blue) and detections (green)" },
			{ "overlay-frames", "LIST", "frames drawn by --overlays (default 1,200,400,600)" },
			{ "overlay-score", "S", "draw detections scoring at least S (default 30)" },
			{ "markdown", "FILE", "the tables and links to the plots and overlays, as Markdown" },
			{ "max-frames", "N", "process only the first N frames" },
			{ "jobs", "N", "runs at the same time, each in its own process (default 1)" },
			{ "score-only", "LIST", "score detection CSVs (frame,x,y,w,h,score) instead of running" },
			{ "num-frames", "N", "frames the CSVs cover, when --frames does not say" },
			{ "label", "NAME", "method name of a single --score-only file (default: file name)" },
			{ "quiet", nullptr, "no progress or notices on standard error" },
		});
	}();
	return table;
}

bool parseEvalOptions(int argc, const char *const *argv, EvalOptions &out, std::string &error)
{
	out = EvalOptions();
	apps::ParsedArgs args;
	if (!apps::parseArgs(argc, argv, evalOptionTable(), false, args, error))
		return false;
	out.help = args.help;
	out.version = args.version;
	if (out.help || out.version)
		return true;
	bool methodsGiven = false;
	for (const apps::ParsedOption &o : args.options) {
		const std::string &arg = o.name;
		const std::string &value = o.value;
		if (apps::takeDetectorOption(o, out.detector, error)) {
			if (!error.empty())
				return false;
			continue;
		}
		auto positive = [&](long &dst, long max) {
			return apps::wholeIn(o, 1, max, dst, error);
		};

		if (arg == "quiet") {
			out.quiet = true;
		} else if (arg == "frames") {
			out.framesDir = value;
		} else if (arg == "video") {
			out.video = value;
		} else if (arg == "size") {
			out.videoSize = value;
		} else if (arg == "gt") {
			out.gt = value;
		} else if (arg == "methods") {
			out.methods = splitList(value);
			methodsGiven = true;
			for (const std::string &m : out.methods) {
				if (!findMethod(m)) {
					error = "unknown method '" + m + "' (known: " + methodNames() + ")";
					return false;
				}
			}
			if (out.methods.empty()) {
				error = o.flag + " needs at least one method (known: " + methodNames() + ")";
				return false;
			}
		} else if (arg == "resizes") {
			out.resizes.clear();
			for (const std::string &s : splitList(value)) {
				double r;
				if (!apps::parseNumber(s, r) || !(r > 0 && r <= 8)) {
					error = o.flag + ": '" + s + "' is not a number in (0, 8]";
					return false;
				}
				// A resize named twice would only overwrite its own output files.
				if (std::find(out.resizes.begin(), out.resizes.end(), r) == out.resizes.end())
					out.resizes.push_back(r);
			}
			if (out.resizes.empty()) {
				error = o.flag + " needs at least one value";
				return false;
			}
		} else if (arg == "json") {
			out.jsonPath = value;
		} else if (arg == "dets") {
			out.detsDir = value;
		} else if (arg == "frames-jsonl") {
			out.framesJsonlDir = value;
		} else if (arg == "plots") {
			out.plotsDir = value;
		} else if (arg == "overlays") {
			out.overlayDir = value;
		} else if (arg == "markdown") {
			out.markdownPath = value;
		} else if (arg == "overlay-frames") {
			out.overlayFrames.clear();
			for (const std::string &s : splitList(value)) {
				long f;
				if (!apps::parseWhole(s, f) || f < 1) {
					error = o.flag + ": '" + s + "' is not a frame number >= 1";
					return false;
				}
				out.overlayFrames.push_back(f);
			}
		} else if (arg == "overlay-score") {
			if (!apps::parseNumber(value, out.overlayScore)) {
				error = apps::badValue(o, "a number");
				return false;
			}
		} else if (arg == "max-frames") {
			if (!positive(out.maxFrames, 100000000))
				return false;
		} else if (arg == "num-frames") {
			if (!positive(out.numFrames, 100000000))
				return false;
		} else if (arg == "jobs") {
			long jobs;
			if (!positive(jobs, 64))
				return false;
			out.jobs = static_cast<int>(jobs);
		} else if (arg == "score-only") {
			out.scoreOnly = splitList(value);
			if (out.scoreOnly.empty()) {
				error = o.flag + " needs at least one CSV file";
				return false;
			}
		} else if (arg == "label") {
			out.label = value;
		}
	}
	out.model = out.detector.model;
	out.calib = out.detector.calibPath;

	if (out.gt.empty()) {
		error = "--gt FILE is required";
		return false;
	}
	if (!out.scoreOnly.empty()) {
		if (!out.video.empty() || !out.model.empty() || methodsGiven) {
			error = "--score-only scores existing detections: --video, --model and --methods do not apply";
			return false;
		}
		if (out.framesDir.empty() == (out.numFrames == 0)) {
			error = "--score-only needs the number of frames: --frames DIR or --num-frames N (one of them)";
			return false;
		}
		if (!out.label.empty() && out.scoreOnly.size() != 1) {
			error = "--label names a single --score-only file";
			return false;
		}
		return true;
	}
	if (out.framesDir.empty() == out.video.empty()) {
		error = "give the frames with exactly one of --frames DIR or --video FILE";
		return false;
	}
	if (!out.videoSize.empty() && out.video.empty()) {
		error = "--size applies to --video only";
		return false;
	}
	if (out.model.empty()) {
		error = "--model BLOB is required";
		return false;
	}
	if (out.numFrames || !out.label.empty()) {
		error = "--num-frames and --label apply to --score-only only";
		return false;
	}
	for (double r : out.resizes) {
		out.detector.resize = r;
		if (!apps::checkDetectorOptions(out.detector, false, apps::DetectorFlags::Eval, error))
			return false;
	}
	out.detector.resize = 1.0; // each run sets its own
	return true;
}

} // namespace calped::eval_tool
