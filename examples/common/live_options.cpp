// SPDX-License-Identifier: BSD-2-Clause
#include "live_options.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace calped {
namespace live {

bool parseNumber(const std::string &text, double &out)
{
	if (text.empty())
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
	if (text.empty())
		return false;
	errno = 0;
	char *end = nullptr;
	const long v = std::strtol(text.c_str(), &end, 10);
	if (errno != 0 || end != text.c_str() + text.size())
		return false;
	out = v;
	return true;
}

namespace {

bool split(int argc, const char *const *argv, const std::vector<std::string> &flags,
	   const std::vector<std::string> *valued, std::vector<Arg> &out, std::string &error)
{
	static const char *const kCommonFlags[] = { "--quiet", "--resize-in-pyramid",
						    "--calibrated-pyramid", "--reject-static",
						    "--help", "-h" };
	static const char *const kCommonValued[] = { "--model", "--calib", "--method", "--resize",
						     "--min-height", "--max-height", "--overlay",
						     "--overlay-every", "--frames", "--timeout",
						     "--stats-every" };
	out.clear();
	for (int i = 1; i < argc; i++) {
		const std::string text = argv[i];
		if (text.size() < 2 || text[0] != '-') {
			error = "unexpected argument '" + text + "' (try --help)";
			return false;
		}
		Arg arg;
		const size_t eq = text.find('=');
		if (text.compare(0, 2, "--") == 0 && eq != std::string::npos) {
			arg.name = text.substr(0, eq);
			arg.value = text.substr(eq + 1);
			arg.hasValue = true;
		} else {
			arg.name = text;
		}
		bool isFlag = std::find(flags.begin(), flags.end(), arg.name) != flags.end();
		for (const char *f : kCommonFlags)
			isFlag = isFlag || arg.name == f;
		bool isValued = !valued || std::find(valued->begin(), valued->end(), arg.name) != valued->end();
		for (const char *v : kCommonValued)
			isValued = isValued || arg.name == v;
		if (!isFlag && !isValued) {
			error = "unknown option '" + arg.name + "' (try --help)";
			return false;
		}
		if (isFlag && arg.hasValue) {
			error = arg.name + " takes no value";
			return false;
		}
		if (!isFlag && !arg.hasValue) {
			if (i + 1 >= argc) {
				error = "option " + arg.name + " needs a value";
				return false;
			}
			arg.value = argv[++i];
			arg.hasValue = true;
		}
		out.push_back(arg);
	}
	return true;
}

} // namespace

bool splitArgs(int argc, const char *const *argv, const std::vector<std::string> &flags,
	       const std::vector<std::string> &valued, std::vector<Arg> &out, std::string &error)
{
	return split(argc, argv, flags, &valued, out, error);
}

bool splitArgs(int argc, const char *const *argv, const std::vector<std::string> &flags,
	       std::vector<Arg> &out, std::string &error)
{
	return split(argc, argv, flags, nullptr, out, error);
}

ParseResult parseLiveOption(const Arg &arg, LiveOptions &out, std::string &error)
{
	const std::string &n = arg.name;
	const std::string &v = arg.value;
	if (n == "-h" || n == "--help") {
		out.help = true;
	} else if (n == "--resize-in-pyramid") {
		out.resizeInPyramid = true;
	} else if (n == "--calibrated-pyramid") {
		out.calibratedPyramid = true;
	} else if (n == "--reject-static") {
		out.rejectStatic = true;
	} else if (n == "--quiet") {
		out.quiet = true;
	} else if (n == "--model" || n == "--calib" || n == "--overlay") {
		if (v.empty()) {
			error = n + " needs a file or folder name";
			return ParseResult::Error;
		}
		(n == "--model" ? out.model : n == "--calib" ? out.calibPath : out.overlayDir) = v;
	} else if (n == "--method") {
		if (v != "generic" && v != "calibrated") {
			error = "--method must be generic or calibrated, got '" + v + "'";
			return ParseResult::Error;
		}
		out.calibrated = v == "calibrated";
	} else if (n == "--resize") {
		double r = 0;
		if (!parseNumber(v, r) || !(r > 0) || r > 8) {
			error = "--resize must be a number > 0 and <= 8, got '" + v + "'";
			return ParseResult::Error;
		}
		out.resize = r;
	} else if (n == "--min-height" || n == "--max-height") {
		double h = 0;
		if (!parseNumber(v, h) || !(h > 0) || h >= 10) {
			error = n + " must be a height in metres, > 0 and < 10, got '" + v + "'";
			return ParseResult::Error;
		}
		(n == "--min-height" ? out.minHeight : out.maxHeight) = h;
	} else if (n == "--overlay-every" || n == "--frames" || n == "--timeout") {
		long k = 0;
		const long lo = 1, hi = n == "--timeout" ? 600000L : 1000000000000L;
		if (!parseWhole(v, k) || k < lo || k > hi) {
			error = n + " must be a whole number from " + std::to_string(lo) + " to " +
				std::to_string(hi) + ", got '" + v + "'";
			return ParseResult::Error;
		}
		if (n == "--overlay-every")
			out.overlayEvery = static_cast<int>(std::min(k, 1000000000L));
		else if (n == "--frames")
			out.frames = k;
		else
			out.timeoutMs = static_cast<int>(k);
	} else if (n == "--stats-every") {
		double s = 0;
		if (!parseNumber(v, s) || !(s > 0) || s > 86400) {
			error = "--stats-every must be seconds > 0, got '" + v + "'";
			return ParseResult::Error;
		}
		out.statsEvery = s;
	} else {
		return ParseResult::NotMine;
	}
	return ParseResult::Ok;
}

bool checkLiveOptions(const LiveOptions &options, std::string &error)
{
	if (options.model.empty()) {
		error = "missing --model BLOB (try --help)";
		return false;
	}
	if (options.calibrated && options.calibPath.empty()) {
		error = "--method calibrated needs --calib FILE";
		return false;
	}
	if (options.minHeight > options.maxHeight) {
		error = "--min-height is above --max-height";
		return false;
	}
	return true;
}

const char *liveUsageText()
{
	return "detector and output options:\n"
	       "  --model BLOB        calped model blob (.cpm, made by calped-convert)\n"
	       "  --calib FILE        camera calibration: detections gain ground position and height\n"
	       "  --method M          generic (default) or calibrated (needs --calib)\n"
	       "  --resize R          upscale frames by R before detecting, 0 < R <= 8 (default 1)\n"
	       "  --resize-in-pyramid do the resize (>= 1) inside the feature pyramid (faster)\n"
	       "  --calibrated-pyramid calibrated: channels at levels placed among the needed ones\n"
	       "  --reject-static     drop detections on static scene structure\n"
	       "  --min-height H      smallest plausible person, metres (default 1.4)\n"
	       "  --max-height H      tallest plausible person, metres (default 2.2)\n"
	       "  --overlay DIR       save DIR/NNNNNNNN.png (frame id) with the detections drawn\n"
	       "  --overlay-every K   overlay every K-th processed frame (default 1)\n"
	       "  --frames N          stop after N processed frames, exit status 0\n"
	       "  --timeout MS        wait per frame before counting a timeout (default 2000)\n"
	       "  --stats-every S     seconds between stats lines on stderr (default 5)\n"
	       "  --quiet             no stats lines\n"
	       "  -h, --help          show this help\n"
	       "\n"
	       "Standard output: one JSON object per processed frame (docs/ports.md).\n"
	       "SIGINT and SIGTERM stop cleanly (exit status 0).\n"
	       "exit status: 0 success, 1 runtime error (camera lost, bad model, ...), 2 usage error\n";
}

} // namespace live
} // namespace calped
