// SPDX-License-Identifier: BSD-2-Clause
// calped-calibrate: estimates a projection matrix with the direct linear transform from
// image/world point correspondences and writes it in calped's plain P format.
// See docs/calibration.md.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include <calped/calibration.h>

#include "correspondences.h"
#include "file_io.h"

namespace calped::calibrate_tool {

namespace {

constexpr int kExitRuntime = 1;
constexpr int kExitUsage = 2;

struct Options {
	std::string input;
	std::string output; // empty: standard output
	LengthUnit unit = LengthUnit::Metre;
	bool quiet = false;
};

const char kUsage[] =
	"usage: calped-calibrate [--unit mm|cm|m] [-o FILE] [--quiet] POINTS.csv\n"
	"\n"
	"Estimates the 3x4 projection matrix P from >= 6 image/world correspondences with the\n"
	"normalised direct linear transform, reports the reprojection error and writes P as\n"
	"text (docs/calibration.md).\n"
	"\n"
	"  POINTS.csv       header 'u,v,X,Y,Z', then one correspondence per line: pixel\n"
	"                   (undistorted) and world point; world z up, ground at z = 0\n"
	"  --unit U         unit of X, Y, Z: mm, cm or m (default m); written as 'unit: U'\n"
	"  -o, --output F   write P to F instead of standard output\n"
	"  --quiet          no report on standard error (errors are still printed)\n"
	"  -h, --help       this text\n";

int fail(int code, const std::string &message)
{
	std::fprintf(stderr, "calped-calibrate: %s\n", message.c_str());
	return code;
}

// Strips the "Code: " prefix of a Status message for the tool's one-line errors.
std::string statusText(const Status &st)
{
	const char *text = st.message();
	const size_t skip = std::strlen(errorCodeName(st.code())) + 2;
	return std::strlen(text) >= skip ? text + skip : text;
}

// 0 when parsed, else the exit code (help prints usage and returns -1 for "exit 0").
int parseArgs(int argc, char **argv, Options &opt)
{
	bool endOfOptions = false;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		if (!endOfOptions && arg == "--") {
			endOfOptions = true;
			continue;
		}
		if (endOfOptions || arg.empty() || arg[0] != '-' || arg == "-") {
			if (!opt.input.empty())
				return fail(kExitUsage, "more than one input file (see --help)");
			opt.input = arg;
			continue;
		}
		std::string value;
		bool hasValue = false;
		const size_t eq = arg.find('=');
		if (arg.compare(0, 2, "--") == 0 && eq != std::string::npos) {
			value = arg.substr(eq + 1);
			arg = arg.substr(0, eq);
			hasValue = true;
		}
		auto takeValue = [&]() {
			if (hasValue)
				return true;
			if (i + 1 >= argc)
				return false;
			value = argv[++i];
			return true;
		};
		if (arg == "-h" || arg == "--help") {
			std::fputs(kUsage, stdout);
			return -1;
		} else if (arg == "--quiet") {
			opt.quiet = true;
		} else if (arg == "--unit") {
			if (!takeValue())
				return fail(kExitUsage, "--unit needs a value (mm, cm or m)");
			if (!parseLengthUnit(value.data(), value.size(), opt.unit))
				return fail(kExitUsage, "--unit '" + value + "' is not mm, cm or m");
		} else if (arg == "-o" || arg == "--output") {
			if (!takeValue() || value.empty())
				return fail(kExitUsage, arg + " needs a file name");
			opt.output = value;
		} else {
			return fail(kExitUsage, "unknown option " + arg + " (see --help)");
		}
		if (hasValue && arg != "--unit" && arg != "--output")
			return fail(kExitUsage, arg + " takes no value");
	}
	if (opt.input.empty())
		return fail(kExitUsage, "no correspondence file given (see --help)");
	return 0;
}

int run(const Options &opt)
{
	std::string text, error;
	if (!readTextFile(opt.input, text, error))
		return fail(kExitRuntime, error);

	Correspondences c;
	Status st = parseCorrespondences(text.data(), text.size(), opt.input.c_str(), c);
	if (!st.ok())
		return fail(kExitRuntime, statusText(st));

	DltResult dlt;
	st = estimateProjectionDlt(c.points.data(), c.points.size(), dlt);
	if (!st.ok())
		return fail(kExitRuntime, opt.input + ": " + statusText(st));

	// The same checks as any calibration file: finite centre above the ground, z up.
	CameraModel camera;
	st = CameraModel::fromProjection(dlt.projection, opt.unit, camera);
	if (!st.ok())
		return fail(kExitRuntime, opt.input + ": estimated P is not usable: " +
					  statusText(st));

	char report[256];
	std::snprintf(report, sizeof(report),
		      "reprojection error RMS %.6g px, max %.6g px (line %d)", dlt.rmsError,
		      dlt.maxError, c.lines[dlt.worstPoint]);
	// Rounding noise would print as "-0.0000".
	Eigen::Vector3d C = camera.centre();
	for (int i = 0; i < 3; i++)
		if (std::abs(C(i)) < 5e-5)
			C(i) = 0.0;
	char centre[160];
	std::snprintf(centre, sizeof(centre), "camera centre (x, y, z) = (%.4f, %.4f, %.4f) m",
		      C.x(), C.y(), C.z());

	std::string comment = "calped-calibrate: DLT from " + std::to_string(c.points.size()) +
			      " correspondences in " + opt.input + "\n" + report + "\n" + centre;
	std::string out;
	st = formatProjectionText(dlt.projection, opt.unit, comment, out);
	if (!st.ok())
		return fail(kExitRuntime, statusText(st));
	if (opt.output.empty()) {
		std::fputs(out.c_str(), stdout);
		if (std::fflush(stdout) != 0)
			return fail(kExitRuntime, "cannot write standard output");
	} else if (!writeTextFile(opt.output, out, error)) {
		return fail(kExitRuntime, error);
	}

	if (!opt.quiet) {
		std::fprintf(stderr, "calped-calibrate: %zu correspondences, world unit %s\n",
			     c.points.size(), lengthUnitName(opt.unit));
		std::fprintf(stderr, "calped-calibrate: %s\n", report);
		std::fprintf(stderr, "calped-calibrate: %s\n", centre);
		if (!opt.output.empty())
			std::fprintf(stderr, "calped-calibrate: wrote %s\n", opt.output.c_str());
	}
	return 0;
}

} // namespace

} // namespace calped::calibrate_tool

int main(int argc, char **argv)
{
	using namespace calped::calibrate_tool;
	Options opt;
	const int parsed = parseArgs(argc, argv, opt);
	if (parsed != 0)
		return parsed < 0 ? 0 : parsed;
	return run(opt);
}
