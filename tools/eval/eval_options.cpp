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

const char *evalUsageText()
{
	return "usage: calped-eval (--frames DIR | --video FILE [--size WxH]) --gt FILE --model BLOB\n"
	       "                   [--calib FILE] [--methods generic[,calibrated]] [--resizes 1.5,2.0,2.5]\n"
	       "                   [--json FILE] [--dets DIR] [--plots DIR] [--overlays DIR]\n"
	       "                   [--overlay-frames 1,200,400,600] [--overlay-score S] [--markdown FILE]\n"
	       "                   [--resize-in-pyramid] [--calibrated-pyramid] [--max-frames N]\n"
	       "                   [--jobs N] [--quiet]\n"
	       "       calped-eval --score-only DETS.csv[,DETS.csv...] --gt FILE\n"
	       "                   (--frames DIR | --num-frames N) [--label NAME] [--json FILE] [--plots DIR]\n"
	       "\n"
	       "Runs the detector over a frame sequence against ground truth (CVML XML or MOTChallenge\n"
	       "gt.txt) and prints the thesis-style table: scales (octaves), classifier applications per\n"
	       "frame, TPR and FPPF (greedy matching at IoU >= 0.5), the thesis's any-overlap TPR, the\n"
	       "log-average miss rate, detector time and peak memory. See docs/evaluation.md.\n"
	       "\n"
	       "  --frames DIR          images of the sequence, sorted by name; frame k is the k-th\n"
	       "  --video FILE          a video decoded through an ffmpeg pipe (needs ffmpeg)\n"
	       "  --size WxH            the video's frame size (default: asked from ffprobe)\n"
	       "  --gt FILE             ground truth: CVML XML (frames 0-based) or MOTChallenge gt.txt\n"
	       "  --model BLOB          calped model blob (calped-convert)\n"
	       "  --calib FILE          camera calibration (Tsai XML, Town Centre .ci, projection\n"
	       "                        matrix, OpenCV YAML), for the calibrated method\n"
	       "  --methods LIST        generic, calibrated, calibrated-static (default generic);\n"
	       "                        the calibrated ones need --calib and are skipped with a\n"
	       "                        notice without it\n"
	       "  --resizes LIST        input resizes (default 1.0)\n"
	       "  --resize-in-pyramid   resize inside the feature pyramid (the toolbox's nOctUp)\n"
	       "                        instead of resampling each frame first; resizes >= 1\n"
	       "  --calibrated-pyramid  calibrated methods compute channels at levels placed among\n"
	       "                        the needed ones instead of the toolbox's octaves\n"
	       "  --json FILE           one JSON object per (method, resize)\n"
	       "  --dets DIR            DIR/<method>_r<resize>.csv: frame,x,y,w,h,score\n"
	       "  --plots DIR           TPR-vs-FPPF and stage-time PNG plots (needs gnuplot)\n"
	       "  --overlays DIR        frames with ground truth (blue) and detections (green)\n"
	       "  --overlay-frames LIST frames drawn by --overlays (default 1,200,400,600)\n"
	       "  --overlay-score S     draw detections scoring at least S (default 30)\n"
	       "  --markdown FILE       the tables and links to the plots and overlays, as Markdown\n"
	       "  --max-frames N        process only the first N frames\n"
	       "  --jobs N              runs at the same time, each in its own process (default 1)\n"
	       "  --score-only LIST     score detection CSVs (frame,x,y,w,h,score) instead of running\n"
	       "  --num-frames N        frames the CSVs cover, when --frames does not say\n"
	       "  --label NAME          method name of a single --score-only file (default: file name)\n"
	       "  --quiet               no progress or notices on standard error\n"
	       "  -h, --help            this text\n";
}

bool parseEvalOptions(int argc, const char *const *argv, EvalOptions &out, std::string &error)
{
	out = EvalOptions();
	bool methodsGiven = false;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		if (arg == "-h" || arg == "--help") {
			out.help = true;
			return true;
		}
		if (arg == "--quiet" || arg == "--resize-in-pyramid" || arg == "--calibrated-pyramid") {
			(arg == "--quiet" ? out.quiet
			 : arg == "--resize-in-pyramid" ? out.resizeInPyramid
							 : out.calibratedPyramid) = true;
			continue;
		}
		std::string value;
		const size_t eq = arg.find('=');
		if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
			value = arg.substr(eq + 1);
			arg = arg.substr(0, eq);
		} else {
			if (arg.rfind("--", 0) != 0) {
				error = "unexpected argument '" + arg + "' (see --help)";
				return false;
			}
			if (i + 1 >= argc) {
				error = "option " + arg + " needs a value";
				return false;
			}
			value = argv[++i];
		}

		auto positive = [&](long &dst, long max) {
			long v;
			if (!parseLong(value, v) || v < 1 || v > max) {
				error = arg + " must be a whole number from 1 to " + std::to_string(max) +
					", got '" + value + "'";
				return false;
			}
			dst = v;
			return true;
		};

		if (arg == "--frames") {
			out.framesDir = value;
		} else if (arg == "--video") {
			out.video = value;
		} else if (arg == "--size") {
			out.videoSize = value;
		} else if (arg == "--gt") {
			out.gt = value;
		} else if (arg == "--model") {
			out.model = value;
		} else if (arg == "--calib") {
			out.calib = value;
		} else if (arg == "--methods") {
			out.methods = splitList(value);
			methodsGiven = true;
			for (const std::string &m : out.methods) {
				if (!findMethod(m)) {
					error = "unknown method '" + m + "' (known: " + methodNames() + ")";
					return false;
				}
			}
			if (out.methods.empty()) {
				error = "--methods needs at least one method (known: " + methodNames() + ")";
				return false;
			}
		} else if (arg == "--resizes") {
			out.resizes.clear();
			for (const std::string &s : splitList(value)) {
				double r;
				if (!parseDouble(s, r) || !(r > 0 && r <= 8)) {
					error = "--resizes: '" + s + "' is not a number in (0, 8]";
					return false;
				}
				// A resize named twice would only overwrite its own output files.
				if (std::find(out.resizes.begin(), out.resizes.end(), r) == out.resizes.end())
					out.resizes.push_back(r);
			}
			if (out.resizes.empty()) {
				error = "--resizes needs at least one value";
				return false;
			}
		} else if (arg == "--json") {
			out.jsonPath = value;
		} else if (arg == "--dets") {
			out.detsDir = value;
		} else if (arg == "--plots") {
			out.plotsDir = value;
		} else if (arg == "--overlays") {
			out.overlayDir = value;
		} else if (arg == "--markdown") {
			out.markdownPath = value;
		} else if (arg == "--overlay-frames") {
			out.overlayFrames.clear();
			for (const std::string &s : splitList(value)) {
				long f;
				if (!parseLong(s, f) || f < 1) {
					error = "--overlay-frames: '" + s + "' is not a frame number >= 1";
					return false;
				}
				out.overlayFrames.push_back(f);
			}
		} else if (arg == "--overlay-score") {
			if (!parseDouble(value, out.overlayScore)) {
				error = "--overlay-score must be a number, got '" + value + "'";
				return false;
			}
		} else if (arg == "--max-frames") {
			if (!positive(out.maxFrames, 100000000))
				return false;
		} else if (arg == "--num-frames") {
			if (!positive(out.numFrames, 100000000))
				return false;
		} else if (arg == "--jobs") {
			long jobs;
			if (!positive(jobs, 64))
				return false;
			out.jobs = static_cast<int>(jobs);
		} else if (arg == "--score-only") {
			out.scoreOnly = splitList(value);
			if (out.scoreOnly.empty()) {
				error = "--score-only needs at least one CSV file";
				return false;
			}
		} else if (arg == "--label") {
			out.label = value;
		} else {
			error = "unknown option " + arg + " (see --help)";
			return false;
		}
	}

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
	return true;
}

} // namespace calped::eval_tool
