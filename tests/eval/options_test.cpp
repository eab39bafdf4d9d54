// SPDX-License-Identifier: BSD-2-Clause
// calped-eval's command line and its output file names.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "eval_options.h"
#include "methods.h"
#include "overlay_frames.h"

namespace calped::eval_tool {
namespace {

bool parse(std::vector<std::string> args, EvalOptions &opt, std::string &error)
{
	args.insert(args.begin(), "calped-eval");
	std::vector<const char *> argv;
	for (const std::string &a : args)
		argv.push_back(a.c_str());
	return parseEvalOptions(static_cast<int>(argv.size()), argv.data(), opt, error);
}

TEST(EvalOptions, ListsAndDefaults)
{
	EvalOptions o;
	std::string error;
	ASSERT_TRUE(parse({ "--frames", "f", "--gt", "g", "--model=m", "--methods", "generic,calibrated",
			    "--resizes", "1.5, 2.0,2.5,2.0" },
			  o, error))
		<< error;
	EXPECT_EQ(o.methods, (std::vector<std::string>{ "generic", "calibrated" }));
	EXPECT_EQ(o.resizes, (std::vector<double>{ 1.5, 2.0, 2.5 })); // the repeated 2.0 dropped
	EXPECT_EQ(o.model, "m");
	EXPECT_EQ(o.jobs, 1);
	EXPECT_EQ(o.overlayFrames, (std::vector<long>{ 1, 200, 400, 600 }));
}

TEST(EvalOptions, UsageErrors)
{
	EvalOptions o;
	std::string error;
	EXPECT_FALSE(parse({ "--frames", "f", "--model", "m" }, o, error));
	EXPECT_NE(error.find("--gt"), std::string::npos) << error;
	EXPECT_FALSE(parse({ "--frames", "f", "--video", "v", "--gt", "g", "--model", "m" }, o, error));
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--resizes", "0" }, o, error));
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--resizes", "two" }, o, error));
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--jobs", "0" }, o, error));
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--max-frames" }, o, error));
	EXPECT_NE(error.find("needs a value"), std::string::npos) << error;
	EXPECT_FALSE(parse({ "--score-only", "a.csv", "--gt", "g", "--num-frames", "5", "--model", "m" },
			   o, error));
	EXPECT_FALSE(parse({ "--score-only", "a.csv,b.csv", "--gt", "g", "--num-frames", "5", "--label", "x" },
			   o, error));
	EXPECT_TRUE(parse({ "--score-only", "a.csv", "--gt", "g", "--num-frames", "5", "--label", "x" }, o, error))
		<< error;
}

TEST(EvalOptions, DetectorFlagsAndTheirDefaults)
{
	EvalOptions o;
	std::string error;
	ASSERT_TRUE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--calib=c.xml" }, o, error)) << error;
	EXPECT_EQ(o.calib, "c.xml");
	EXPECT_EQ(o.detector.calibPath, "c.xml");
	EXPECT_EQ(o.detector.resizeAt, apps::ResizeChoice::Default);
	EXPECT_EQ(o.detector.levels, apps::LevelsChoice::Default);
	ASSERT_TRUE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--resize-at", "frame",
			    "--levels=toolbox", "--resizes", "0.5,2" },
			  o, error))
		<< error;
	EXPECT_EQ(o.detector.resizeAt, apps::ResizeChoice::Frame);
	EXPECT_EQ(o.detector.levels, apps::LevelsChoice::Toolbox);
	// The pyramid only upscales; placed levels need the frame at its own size.
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--resize-at", "pyramid",
			     "--resizes", "0.5" },
			   o, error));
	EXPECT_NE(error.find("--resize-at pyramid"), std::string::npos) << error;
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--resize-at", "frame",
			     "--levels", "placed", "--resizes", "2" },
			   o, error));
	EXPECT_NE(error.find("--levels placed"), std::string::npos) << error;
	// Unknown options are named as written (not "needs a value").
	EXPECT_FALSE(parse({ "--frames", "f", "--gt", "g", "--model", "m", "--bogus" }, o, error));
	EXPECT_EQ(error, "unknown option '--bogus' (try --help)");
	ASSERT_TRUE(parse({ "--version" }, o, error)) << error;
	EXPECT_TRUE(o.version);
}

TEST(Methods, RegistryKnowsBothModes)
{
	ASSERT_NE(findMethod("generic"), nullptr);
	ASSERT_NE(findMethod("calibrated"), nullptr);
	EXPECT_EQ(findMethod("fastest"), nullptr);
	EXPECT_NE(findMethod("generic")->create, nullptr);
	EXPECT_NE(findMethod("calibrated")->create, nullptr);
	EXPECT_FALSE(findMethod("generic")->needsCalibration);
	EXPECT_TRUE(findMethod("calibrated")->needsCalibration);
	ASSERT_NE(findMethod("calibrated-static"), nullptr);
	EXPECT_TRUE(findMethod("calibrated-static")->needsCalibration);
	EXPECT_EQ(methodNames(), "generic, calibrated, calibrated-static");
}

TEST(OutputNames, ResizeWithOneDecimalUnlessMoreAreNeeded)
{
	EXPECT_EQ(runStem("generic", 2.0), "generic_r2.0");
	EXPECT_EQ(runStem("calibrated", 1.5), "calibrated_r1.5");
	EXPECT_EQ(runStem("generic", 1.25), "generic_r1.25");
	EXPECT_EQ(resizeLabel(0.75), "0.75");
}

} // namespace
} // namespace calped::eval_tool
