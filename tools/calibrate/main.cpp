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
#include "file_io.h" // tools/common
#include "cli_error.h"
#include "program.h"

namespace calped::calibrate_tool {

using apps::readTextFile;
using apps::statusText;
using apps::writeTextFile;

namespace {

using apps::kExitRuntime;

struct Options {
	std::string input;
	std::string output; // empty: standard output
	LengthUnit unit = LengthUnit::Metre;
	bool quiet = false;
};

const apps::ProgramInfo kProgram = {
	"calped-calibrate",
	"usage: calped-calibrate [--unit mm|cm|m] [-o FILE] [--quiet] POINTS.csv\n"
	"\n"
	"Estimates the 3x4 projection matrix P from >= 6 image/world correspondences with the\n"
	"normalised direct linear transform, reports the reprojection error and writes P as\n"
	"text (docs/calibration.md).\n"
	"\n"
	"  POINTS.csv       header 'u,v,X,Y,Z', then one correspondence per line: pixel\n"
	"                   (undistorted) and world point; world z up, ground at z = 0\n"
	"\n"
	"options:\n",
	"\n"
	"exit status: 0 success, 1 runtime error, 2 usage error\n",
};

const std::vector<apps::OptionSpec> kOptions = {
	{ "unit", "U", "unit of X, Y, Z: mm, cm or m (default m); written as 'unit: U'" },
	{ "output", "FILE", "write P to FILE instead of standard output", 'o' },
	{ "quiet", nullptr, "no report on standard error (errors are still printed)" },
};

int fail(int code, const std::string &message)
{
	return apps::cliFail(kProgram.name, code, message);
}

// -1 when parsed, else the exit code.
int parseArgs(int argc, char **argv, Options &opt)
{
	apps::ParsedArgs args;
	const int rc = apps::parseCommandLine(kProgram, kOptions, true, argc, argv, args);
	if (rc >= 0)
		return rc;
	std::string error;
	for (const apps::ParsedOption &o : args.options) {
		if (o.name == "quiet")
			opt.quiet = true;
		else if (o.name == "unit" && !parseLengthUnit(o.value.data(), o.value.size(), opt.unit))
			return apps::usageError(kProgram, apps::badValue(o, "mm, cm or m"));
		else if (o.name == "output" && !apps::nonEmpty(o, "a file name", opt.output, error))
			return apps::usageError(kProgram, error);
	}
	if (args.positional.empty())
		return apps::usageError(kProgram, "no correspondence file given (see --help)");
	if (args.positional.size() > 1)
		return apps::usageError(kProgram, "more than one input file (see --help)");
	opt.input = args.positional[0];
	return -1;
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
	if (parsed >= 0)
		return parsed;
	return run(opt);
}
