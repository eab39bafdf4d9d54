// SPDX-License-Identifier: BSD-2-Clause
// tools/common's parser and detector flags on their own: what every program's command line
// goes through (the programs themselves are tested as black boxes in programs_test).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "args.h"
#include "detector_options.h"

namespace calped::apps {
namespace {

const std::vector<OptionSpec> kTable = {
	{ "resize", "R", "upscale" },
	{ "resize-at", "WHERE", "where" },
	{ "quiet", nullptr, "no output" },
	{ "output", "FILE", "write there", 'o' },
	{ nullptr, nullptr, "more options:" },
	{ "reject-static", nullptr, "two\nlines" },
};

bool parse(std::vector<std::string> args, ParsedArgs &out, std::string &error, bool positional = true)
{
	args.insert(args.begin(), "prog");
	std::vector<const char *> argv;
	for (const std::string &a : args)
		argv.push_back(a.c_str());
	return parseArgs(static_cast<int>(argv.size()), argv.data(), kTable, positional, out, error);
}

TEST(Args, BothValueFormsPrefixesAndPositionalsAnywhere)
{
	ParsedArgs a;
	std::string error;
	ASSERT_TRUE(parse({ "in1", "--resize=2", "--resize-at", "frame", "in2", "--qu", "-o", "x.txt",
			    "--", "--quiet" },
			  a, error))
		<< error;
	ASSERT_EQ(a.options.size(), 4u);
	EXPECT_EQ(a.options[0].name, "resize");
	EXPECT_EQ(a.options[0].flag, "--resize");
	EXPECT_EQ(a.options[0].value, "2");
	EXPECT_EQ(a.options[1].name, "resize-at");
	EXPECT_EQ(a.options[1].value, "frame");
	EXPECT_EQ(a.options[2].name, "quiet");
	EXPECT_EQ(a.options[2].flag, "--qu"); // as written
	EXPECT_EQ(a.options[3].name, "output");
	EXPECT_EQ(a.options[3].flag, "-o");
	EXPECT_EQ(a.options[3].value, "x.txt");
	EXPECT_EQ(a.positional, (std::vector<std::string>{ "in1", "in2", "--quiet" }));
	// Parsing twice gives the same (getopt's state is reset).
	ParsedArgs b;
	ASSERT_TRUE(parse({ "--resize", "3" }, b, error)) << error;
	ASSERT_EQ(b.options.size(), 1u);
	EXPECT_EQ(b.options[0].value, "3");
}

TEST(Args, UsageErrorsNameTheFlagAsWritten)
{
	ParsedArgs a;
	std::string error;
	EXPECT_FALSE(parse({ "--bogus" }, a, error));
	EXPECT_EQ(error, "unknown option '--bogus' (try --help)");
	EXPECT_FALSE(parse({ "--bogus=1" }, a, error));
	EXPECT_EQ(error, "unknown option '--bogus' (try --help)");
	EXPECT_FALSE(parse({ "-x" }, a, error));
	EXPECT_EQ(error, "unknown option '-x' (try --help)");
	EXPECT_FALSE(parse({ "--quiet=yes" }, a, error));
	EXPECT_EQ(error, "--quiet takes no value");
	EXPECT_FALSE(parse({ "--resize" }, a, error));
	EXPECT_EQ(error, "--resize needs a value (R)");
	EXPECT_FALSE(parse({ "--res", "2" }, a, error));
	EXPECT_EQ(error, "ambiguous option '--res' (could be --resize, --resize-at)");
	EXPECT_FALSE(parse({ "file" }, a, error, false));
	EXPECT_EQ(error, "unexpected argument 'file' (try --help)");
	ASSERT_TRUE(parse({ "--help" }, a, error));
	EXPECT_TRUE(a.help);
	ASSERT_TRUE(parse({ "--version" }, a, error));
	EXPECT_TRUE(a.version);
}

TEST(Args, HelpIsGeneratedFromTheTable)
{
	const std::string help = optionsHelp(kTable);
	EXPECT_NE(help.find("  --resize R"), std::string::npos) << help;
	EXPECT_NE(help.find("  -o, --output FILE"), std::string::npos) << help;
	EXPECT_NE(help.find("\nmore options:\n"), std::string::npos) << help;
	EXPECT_NE(help.find("two\n"), std::string::npos) << help;
	EXPECT_NE(help.find("lines\n"), std::string::npos) << help;
	EXPECT_NE(help.find("--version"), std::string::npos) << help;
}

TEST(Args, NumbersAreWholeAndFinite)
{
	double d = 0;
	long l = 0;
	EXPECT_TRUE(parseNumber("2.5", d));
	EXPECT_EQ(d, 2.5);
	for (const char *bad : { "", "2x", "nan", "inf", "1e400", " 2", "0x2", "0X1p1", "2 " })
		EXPECT_FALSE(parseNumber(bad, d)) << bad;
	EXPECT_TRUE(parseWhole("-3", l));
	EXPECT_EQ(l, -3);
	EXPECT_FALSE(parseWhole("1.5", l));
	int w = 0, h = 0;
	EXPECT_TRUE(parseFrameSize("768x576", w, h));
	EXPECT_EQ(w, 768);
	EXPECT_EQ(h, 576);
	for (const char *bad : { "768", "0x5", "x5", "768x", "20000x10" })
		EXPECT_FALSE(parseFrameSize(bad, w, h)) << bad;
}

// The defaults of docs/cli.md, as makeDetectorConfig turns them into a DetectorConfig.
TEST(DetectorOptions, DefaultsAndTheConfigTheyMake)
{
	DetectorOptions o;
	o.resize = 2;
	DetectorConfig c = makeDetectorConfig(o, 768, 576, nullptr);
	EXPECT_EQ(c.method, DetectionMethod::Generic);
	EXPECT_EQ(c.resizeAt, calped::ResizeAt::Pyramid);
	EXPECT_FALSE(c.calibrated.has_value());
	EXPECT_TRUE(c.validate().ok()) << c.validate().message();
	EXPECT_EQ(c.resize, 2.0);
	EXPECT_EQ(c.maxWidth, 768);
	EXPECT_EQ(c.maxHeight, 576);

	o.calibPath = "View_001.xml"; // --calib alone: the calibrated method, placed levels
	CameraModel camera;
	c = makeDetectorConfig(o, 768, 576, &camera);
	EXPECT_EQ(c.method, DetectionMethod::Calibrated);
	EXPECT_EQ(c.resizeAt, calped::ResizeAt::Pyramid);
	ASSERT_TRUE(c.calibrated.has_value());
	EXPECT_EQ(c.calibrated->levels, PyramidLevels::Placed);
	EXPECT_EQ(c.camera, &camera);
	EXPECT_TRUE(c.calibrated->boxVoting);
	EXPECT_FALSE(c.calibrated->scoreRatio);
	EXPECT_FALSE(c.staticRejection.has_value());

	o.resizeAt = ResizeChoice::Frame; // the thesis's resize: the toolbox's octaves
	c = makeDetectorConfig(o, 768, 576, &camera);
	EXPECT_EQ(c.resizeAt, calped::ResizeAt::Frame);
	EXPECT_EQ(c.calibrated->levels, PyramidLevels::Toolbox);

	o.resizeAt = ResizeChoice::Default;
	o.resize = 0.5; // below 1: the frame, since the pyramid only upscales
	c = makeDetectorConfig(o, 768, 576, &camera);
	EXPECT_EQ(c.resizeAt, calped::ResizeAt::Frame);

	o = DetectorOptions();
	o.model = "m";
	o.calibPath = "c";
	o.method = MethodChoice::Generic;
	o.levels = LevelsChoice::Toolbox;
	std::string error;
	EXPECT_FALSE(checkDetectorOptions(o, true, DetectorFlags::All, error));
	EXPECT_EQ(error, "--levels applies to the calibrated method only (give --calib FILE)");
	EXPECT_TRUE(checkDetectorOptions(o, true, DetectorFlags::Eval, error)) << error;
}

// --threads N: 1..64; without it the online cores (at least 1, at most 64).
TEST(DetectorOptions, Threads)
{
	DetectorOptions o;
	std::string error;
	const int cores = o.detectorThreads();
	EXPECT_GE(cores, 1);
	EXPECT_LE(cores, 64);
	EXPECT_EQ(makeDetectorConfig(o, 640, 480, nullptr).threads, cores);
	ASSERT_TRUE(takeDetectorOption(ParsedOption{ "threads", "--threads", "3" }, o, error));
	EXPECT_TRUE(error.empty()) << error;
	EXPECT_EQ(makeDetectorConfig(o, 640, 480, nullptr).threads, 3);
	for (const char *bad : { "0", "65", "two", "-1" }) {
		DetectorOptions p;
		ASSERT_TRUE(takeDetectorOption(ParsedOption{ "threads", "--threads", bad }, p, error));
		EXPECT_FALSE(error.empty()) << bad;
		EXPECT_NE(error.find("--threads"), std::string::npos) << error;
	}
}

} // namespace
} // namespace calped::apps
