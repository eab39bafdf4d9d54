// SPDX-License-Identifier: BSD-2-Clause
#include "options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace calped::detect_tool {

namespace {

// The whole string must be a finite number: "2x", "" and "nan" are refused.
bool parseDouble(const std::string &text, double &out)
{
	if (text.empty())
		return false;
	errno = 0;
	char *end = nullptr;
	double v = std::strtod(text.c_str(), &end);
	if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(v))
		return false;
	out = v;
	return true;
}

bool parseLong(const std::string &text, long &out)
{
	if (text.empty())
		return false;
	errno = 0;
	char *end = nullptr;
	long v = std::strtol(text.c_str(), &end, 10);
	if (errno != 0 || end != text.c_str() + text.size())
		return false;
	out = v;
	return true;
}

} // namespace

const char *usageText()
{
	return "usage: calped-detect --model BLOB [options] INPUT...\n"
	       "\n"
	       "Runs the calped pedestrian detector on images. Each INPUT is an image file\n"
	       "(PNG, JPEG, PPM, PGM) or a folder whose *.png, *.jpg, *.jpeg, *.ppm and *.pgm\n"
	       "files are taken in name order. Frames are numbered from 1.\n"
	       "\n"
	       "options:\n"
	       "  --model BLOB        calped model blob (.cpm, made by calped-convert)\n"
	       "  --resize R          upscale each frame by R before detecting, 0 < R <= 8 (default 1)\n"
	       "  --resize-in-pyramid do the resize (>= 1) inside the feature pyramid instead\n"
	       "                      (the toolbox's nOctUp; faster, docs/cli.md)\n"
	       "  --calibrated-pyramid with --method calibrated: compute channels at levels placed\n"
	       "                      among the needed ones (needs --resize-in-pyramid or resize 1)\n"
	       "  --csv FILE          write detections as CSV: frame,x,y,w,h,score\n"
	       "  --jsonl FILE|-      write one JSON object per frame (- for standard output)\n"
	       "  --overlay DIR       write DIR/NNNNNN.png with the detections drawn in green\n"
	       "  --overlay-every K   overlay only frames 1, 1+K, 1+2K, ... (default 1)\n"
	       "  --max-frames N      stop after the first N frames\n"
	       "  --no-nms            keep every window that passed the cascade\n"
	       "  --calib FILE        camera calibration (Tsai XML, Town Centre .ci, plain P,\n"
	       "                      OpenCV YAML): detections gain ground position and height\n"
	       "  --method M          generic (default) or calibrated (needs --calib)\n"
	       "  --min-height H      smallest plausible person, metres (default 1.4)\n"
	       "  --max-height H      tallest plausible person, metres (default 2.2)\n"
	       "  --no-box-voting     calibrated: keep the best window's box (the thesis's)\n"
	       "  --reject-static     fixed camera: drop detections on static scene structure\n"
	       "                      (frames must come from one camera, in order; docs/cli.md)\n"
	       "  --quiet             no progress or summary on standard error\n"
	       "  -h, --help          show this help\n"
	       "\n"
	       "exit status: 0 success, 1 runtime error, 2 usage error\n";
}

bool parseOptions(int argc, const char *const *argv, Options &out, std::string &error)
{
	out = Options();
	bool haveModel = false;
	bool optionsDone = false;

	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];

		if (optionsDone || arg.size() < 2 || arg[0] != '-') {
			out.inputs.push_back(arg);
			continue;
		}
		if (arg == "--") {
			optionsDone = true;
			continue;
		}
		if (arg == "-h" || arg == "--help") {
			out.help = true;
			return true;
		}

		// Accept both "--opt value" and "--opt=value".
		std::string name = arg;
		std::string value;
		bool inlineValue = false;
		size_t eq = arg.find('=');
		if (arg.compare(0, 2, "--") == 0 && eq != std::string::npos) {
			name = arg.substr(0, eq);
			value = arg.substr(eq + 1);
			inlineValue = true;
		}

		bool *flag = name == "--no-nms"              ? &out.noNms
			     : name == "--quiet"             ? &out.quiet
			     : name == "--no-box-voting"     ? &out.noBoxVoting
			     : name == "--resize-in-pyramid" ? &out.resizeInPyramid
			     : name == "--calibrated-pyramid" ? &out.calibratedPyramid
			     : name == "--reject-static"     ? &out.rejectStatic
							     : nullptr;
		if (flag) {
			if (inlineValue) {
				error = name + " takes no value";
				return false;
			}
			*flag = true;
			continue;
		}

		static const char *const kValued[] = { "--model", "--resize", "--csv", "--jsonl",
						       "--overlay", "--overlay-every", "--max-frames",
						       "--calib", "--method", "--min-height", "--max-height" };
		bool known = false;
		for (const char *k : kValued)
			known = known || name == k;
		if (!known) {
			error = "unknown option '" + arg + "' (try --help)";
			return false;
		}
		if (!inlineValue) {
			if (i + 1 >= argc) {
				error = "option " + name + " needs a value";
				return false;
			}
			value = argv[++i];
		}

		if (name == "--model") {
			if (value.empty()) {
				error = "--model needs a file name";
				return false;
			}
			out.model = value;
			haveModel = true;
		} else if (name == "--resize") {
			double r = 0;
			if (!parseDouble(value, r) || !(r > 0.0) || r > 8.0) {
				error = "--resize must be a number > 0 and <= 8, got '" + value + "'";
				return false;
			}
			out.resize = r;
		} else if (name == "--csv" || name == "--jsonl" || name == "--overlay") {
			if (value.empty()) {
				error = name + " needs a file or folder name";
				return false;
			}
			(name == "--csv" ? out.csvPath : name == "--jsonl" ? out.jsonlPath : out.overlayDir) = value;
		} else if (name == "--overlay-every") {
			long k = 0;
			if (!parseLong(value, k) || k < 1 || k > 1000000000L) {
				error = "--overlay-every must be a whole number >= 1, got '" + value + "'";
				return false;
			}
			out.overlayEvery = static_cast<int>(k);
		} else if (name == "--calib") {
			if (value.empty()) {
				error = "--calib needs a file name";
				return false;
			}
			out.calibPath = value;
		} else if (name == "--method") {
			if (value != "generic" && value != "calibrated") {
				error = "--method must be generic or calibrated, got '" + value + "'";
				return false;
			}
			out.calibrated = value == "calibrated";
		} else if (name == "--min-height" || name == "--max-height") {
			double h = 0;
			if (!parseDouble(value, h) || !(h > 0.0) || h >= 10.0) {
				error = name + " must be a height in metres, > 0 and < 10, got '" + value + "'";
				return false;
			}
			(name == "--min-height" ? out.minHeight : out.maxHeight) = h;
		} else if (name == "--max-frames") {
			long n = 0;
			if (!parseLong(value, n) || n < 1) {
				error = "--max-frames must be a whole number >= 1, got '" + value + "'";
				return false;
			}
			out.maxFrames = n;
		}
	}

	if (!haveModel) {
		error = "missing --model BLOB (try --help)";
		return false;
	}
	if (out.inputs.empty()) {
		error = "no input images or folders given (try --help)";
		return false;
	}
	if (out.calibrated && out.calibPath.empty()) {
		error = "--method calibrated needs --calib FILE";
		return false;
	}
	if (out.minHeight > out.maxHeight) {
		error = "--min-height is above --max-height";
		return false;
	}
	if (!out.csvPath.empty() && out.csvPath == out.jsonlPath) {
		error = "--csv and --jsonl name the same file";
		return false;
	}
	return true;
}

} // namespace calped::detect_tool
