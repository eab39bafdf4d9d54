// SPDX-License-Identifier: BSD-2-Clause
// calped-detect as a black box: exit codes, one-line errors, and the shape of its outputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "process.h"
#include "test_model.h"

namespace fs = std::filesystem;
using calped::test::ProcessResult;
using calped::test::readTextFile;
using calped::test::runProcess;
using calped::test::splitLines;

// Set by main() from the command line meson passes.
std::string gDetectPath;
std::string gConvertPath;

namespace {

// An error must be exactly one line, prefixed with the program name.
void expectOneLineError(const ProcessResult &r, int code)
{
	ASSERT_TRUE(r.exited) << "killed by signal " << r.signal << "; stderr:\n" << r.err;
	EXPECT_EQ(r.exitCode, code) << "stderr:\n" << r.err;
	std::vector<std::string> lines = splitLines(r.err);
	ASSERT_EQ(lines.size(), 1u) << "stderr:\n" << r.err;
	EXPECT_EQ(lines[0].rfind("calped-detect: ", 0), 0u) << lines[0];
	EXPECT_GT(lines[0].size(), std::string("calped-detect: ").size() + 5);
}

void writePpm(const std::string &path, int w, int h, uint32_t seed)
{
	std::mt19937 rng(seed);
	std::ofstream f(path, std::ios::binary);
	f << "P6\n" << w << " " << h << "\n255\n";
	for (int i = 0; i < w * h * 3; i++)
		f.put(static_cast<char>(rng() & 0xff));
}

// "-12.34" with exactly `decimals` digits after the point.
bool isFixedDecimal(const std::string &s, size_t decimals)
{
	size_t i = (!s.empty() && s[0] == '-') ? 1 : 0;
	size_t digits = 0;
	while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
		i++, digits++;
	if (digits == 0 || i >= s.size() || s[i] != '.')
		return false;
	size_t frac = s.size() - i - 1;
	for (i++; i < s.size(); i++)
		if (!std::isdigit(static_cast<unsigned char>(s[i])))
			return false;
	return frac == decimals;
}

std::vector<std::string> splitCommas(const std::string &line)
{
	std::vector<std::string> fields(1);
	for (char c : line) {
		if (c == ',')
			fields.emplace_back();
		else
			fields.back() += c;
	}
	return fields;
}

// A smooth grey ramp with a dark vertical bar: something with gradients.
std::vector<uint8_t> greyPattern(int w, int h)
{
	std::vector<uint8_t> px(static_cast<size_t>(w) * h);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			bool bar = x >= w / 3 && x < w / 3 + 24 && y >= h / 5 && y < h - h / 5;
			px[static_cast<size_t>(y) * w + x] = bar ? 20 : static_cast<uint8_t>(100 + (x + y) % 120);
		}
	return px;
}

class CliTest : public ::testing::Test
{
protected:
	void SetUp() override
	{
		ASSERT_FALSE(gDetectPath.empty()) << "run with --detect=PATH";
		ASSERT_TRUE(fs::exists(gDetectPath)) << gDetectPath;
		const char *tmp = std::getenv("TMPDIR");
		std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/calped-cli-XXXXXX";
		std::vector<char> buf(pattern.begin(), pattern.end());
		buf.push_back('\0');
		ASSERT_NE(mkdtemp(buf.data()), nullptr);
		dir_ = buf.data();
	}
	void TearDown() override
	{
		std::error_code ec;
		if (!dir_.empty())
			fs::remove_all(dir_, ec);
	}

	ProcessResult detect(const std::vector<std::string> &args)
	{
		return runProcess(gDetectPath, args, dir_);
	}
	std::string path(const std::string &name) const { return dir_ + "/" + name; }

	// A valid image so that tests about the model get past the input checks.
	std::string someImage()
	{
		std::string p = path("img.ppm");
		writePpm(p, 200, 150, 1);
		return p;
	}

	std::string dir_;
};

// ---- usage errors: exit 2 ----

TEST_F(CliTest, NoArgumentsIsAUsageError)
{
	expectOneLineError(detect({}), 2);
}

TEST_F(CliTest, HelpGoesToStdoutAndSucceeds)
{
	ProcessResult r = detect({ "--help" });
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0);
	EXPECT_NE(r.out.find("--model"), std::string::npos);
	EXPECT_NE(r.out.find("--overlay-every"), std::string::npos);
	EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(CliTest, UnknownOptionIsNamed)
{
	ProcessResult r = detect({ "--model", "m.cpm", "--frobnicate", someImage() });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--frobnicate"), std::string::npos) << r.err;
}

TEST_F(CliTest, OptionWithoutValue)
{
	ProcessResult r = detect({ someImage(), "--model" });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--model"), std::string::npos) << r.err;
}

TEST_F(CliTest, MissingModelOption)
{
	ProcessResult r = detect({ someImage() });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--model"), std::string::npos) << r.err;
}

TEST_F(CliTest, MissingInputs)
{
	expectOneLineError(detect({ "--model", "m.cpm" }), 2);
}

class ResizeRejected : public CliTest, public ::testing::WithParamInterface<const char *>
{
};

TEST_P(ResizeRejected, IsAUsageError)
{
	ProcessResult r = detect({ "--model", path("missing.cpm"), "--resize", GetParam(), someImage() });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--resize"), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Values, ResizeRejected,
			 ::testing::Values("abc", "0", "-1", "8.01", "2x", "", "nan", "inf", "1e400"));

TEST_F(CliTest, ResizeBoundsAreAccepted)
{
	// Accepted values get past parsing and fail later, on the missing model (exit 1).
	for (const char *r : { "8", "0.5", "1.5", "2" }) {
		ProcessResult res = detect({ "--model", path("missing.cpm"), "--resize=" + std::string(r), someImage() });
		expectOneLineError(res, 1);
		EXPECT_EQ(res.err.find("--resize"), std::string::npos) << r << ": " << res.err;
	}
}

TEST_F(CliTest, FlagsTakeNoValue)
{
	for (const char *flag : { "--quiet=1", "--reject-static=yes", "--no-nms=0" }) {
		ProcessResult r = detect({ "--model", "m", flag, someImage() });
		expectOneLineError(r, 2);
		EXPECT_NE(r.err.find("takes no value"), std::string::npos) << flag << ": " << r.err;
	}
}

TEST_F(CliTest, BadCountsAreUsageErrors)
{
	std::string img = someImage();
	expectOneLineError(detect({ "--model", "m", "--overlay-every", "0", img }), 2);
	expectOneLineError(detect({ "--model", "m", "--overlay-every", "x", img }), 2);
	expectOneLineError(detect({ "--model", "m", "--max-frames", "-3", img }), 2);
	expectOneLineError(detect({ "--model", "m", "--max-frames", "1.5", img }), 2);
}

// ---- runtime errors: exit 1 ----

TEST_F(CliTest, MissingModelFile)
{
	ProcessResult r = detect({ "--model", path("nowhere.cpm"), someImage() });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("nowhere.cpm"), std::string::npos) << r.err;
}

TEST_F(CliTest, CorruptModelFileReportsTheModel)
{
	std::mt19937 rng(7);
	{
		std::ofstream f(path("random.cpm"), std::ios::binary);
		for (int i = 0; i < 4096; i++)
			f.put(static_cast<char>(rng() & 0xff));
	}
	ProcessResult r = detect({ "--model", path("random.cpm"), someImage() });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("model"), std::string::npos) << r.err;

	// An empty file is corrupt too, not a crash.
	std::ofstream(path("empty.cpm"), std::ios::binary).close();
	r = detect({ "--model", path("empty.cpm"), someImage() });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("model"), std::string::npos) << r.err;
}

TEST_F(CliTest, UndecodableImageIsNamed)
{
	// Inputs are checked before the model is read, so no model is needed here.
	std::ofstream(path("broken.png"), std::ios::binary) << "this is not a PNG";
	ProcessResult r = detect({ "--model", path("nowhere.cpm"), path("broken.png") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("broken.png"), std::string::npos) << r.err;
}

TEST_F(CliTest, UndecodableImageInsideAFolder)
{
	fs::create_directory(path("frames"));
	writePpm(path("frames/000001.ppm"), 64, 64, 2);
	std::ofstream(path("frames/000002.png"), std::ios::binary) << "\x89PNG truncated";
	ProcessResult r = detect({ "--model", path("nowhere.cpm"), path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("000002.png"), std::string::npos) << r.err;
}

// A PPM whose maximum value is not 255 would be read unscaled (127 as a darker image):
// refused by name, before the model is read.
TEST_F(CliTest, PpmMaximumOtherThan255IsRefused)
{
	for (const char *maxval : { "127", "0", "1" }) {
		std::ofstream(path("m.ppm"), std::ios::binary) << "P6\n2 2\n" << maxval << "\n" << std::string(12, '\x10');
		const ProcessResult r = detect({ "--model", path("none.cpm"), path("m.ppm") });
		expectOneLineError(r, 1);
		EXPECT_NE(r.err.find(std::string("maximum value ") + maxval + " is not supported, only 255"),
			  std::string::npos) << r.err;
	}
}

// strtod reads "0x2" as 2: numbers are decimal, the whole value.
TEST_F(CliTest, HexadecimalNumbersAreUsageErrors)
{
	const ProcessResult r = detect({ "--model", "m.cpm", "--resize", "0x2", someImage() });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--resize: expected a number > 0 and <= 8, got '0x2'"), std::string::npos) << r.err;
}

TEST_F(CliTest, MissingInputPath)
{
	ProcessResult r = detect({ "--model", path("nowhere.cpm"), path("no-such-frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("no-such-frames"), std::string::npos) << r.err;
}

TEST_F(CliTest, EmptyFolder)
{
	fs::create_directory(path("empty"));
	std::ofstream(path("empty/readme.txt")) << "not an image\n";
	ProcessResult r = detect({ "--model", path("nowhere.cpm"), path("empty") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
}

// ---- valid runs: need a real model blob ----

class CliRunTest : public CliTest
{
protected:
	// PETS 2009 frame 1 and its calibration, "" when absent (scripts/fetch-pets.sh, ../shared).
	static std::string petsFrame()
	{
		const char *source = std::getenv("CALPED_SOURCE_DIR");
		const std::string frame = std::string(source ? source : ".") + "/data/pets/frames/000001.png";
		return fs::exists(frame) ? frame : "";
	}
	static std::string petsCalib()
	{
		const char *shared = std::getenv("CALPED_SHARED_DIR");
		const std::string calib = std::string(shared ? shared : "../shared") + "/data/pets2009-s2l1/View_001.xml";
		return fs::exists(calib) ? calib : "";
	}

	void SetUp() override
	{
		CliTest::SetUp();
		if (HasFatalFailure())
			return;
		std::string reason;
		model_ = calped::test::convertedModel(gConvertPath, reason);
		if (model_.empty()) {
			// A converter that exists but fails is a failure, not a reason to skip.
			ASSERT_NE(reason.rfind("FAIL: ", 0), 0u) << reason;
			GTEST_SKIP() << reason;
		}

		// Three frames in name order: grey PNG, colour PPM, colour JPEG; plus things to ignore.
		fs::create_directory(path("frames"));
		fs::create_directory(path("frames/sub"));
		std::ofstream(path("frames/notes.txt")) << "ignored\n";
		grey_ = greyPattern(kW, kH);
		ASSERT_TRUE(stbi_write_png(path("frames/a.png").c_str(), kW, kH, 1, grey_.data(), kW));
		writePpm(path("frames/b.ppm"), kW, kH, 3);
		std::vector<uint8_t> rgb(static_cast<size_t>(kW) * kH * 3);
		for (size_t i = 0; i < rgb.size(); i++)
			rgb[i] = grey_[i / 3];
		ASSERT_TRUE(stbi_write_jpg(path("frames/c.JPG").c_str(), kW, kH, 3, rgb.data(), 90));
	}

	static constexpr int kW = 160, kH = 240;
	std::string model_;
	std::vector<uint8_t> grey_;
};

TEST_F(CliRunTest, CsvAndJsonlHaveTheDocumentedShape)
{
	ProcessResult r = detect({ "--model", model_, "--csv", path("d.csv"), "--jsonl", path("d.jsonl"),
				   "--quiet", path("frames") });
	ASSERT_TRUE(r.exited) << "signal " << r.signal << "\n" << r.err;
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_TRUE(r.err.empty()) << "--quiet printed: " << r.err;

	std::vector<std::string> csv = splitLines(readTextFile(path("d.csv")));
	ASSERT_GE(csv.size(), 1u);
	EXPECT_EQ(csv[0], "frame,x,y,w,h,score,ground_x,ground_y,world_height");
	for (size_t i = 1; i < csv.size(); i++) {
		std::vector<std::string> f = splitCommas(csv[i]);
		ASSERT_EQ(f.size(), 9u) << "row " << i << ": " << csv[i];
		// No calibration: the world fields are empty.
		EXPECT_TRUE(f[6].empty() && f[7].empty() && f[8].empty()) << csv[i];
		EXPECT_TRUE(f[0] == "1" || f[0] == "2" || f[0] == "3") << csv[i];
		for (int c = 1; c <= 4; c++)
			EXPECT_TRUE(isFixedDecimal(f[c], 2)) << "column " << c << ": " << csv[i];
		EXPECT_TRUE(isFixedDecimal(f[5], 4)) << "score: " << csv[i];
		EXPECT_GT(std::atof(f[3].c_str()), 0.0) << csv[i];
		EXPECT_GT(std::atof(f[4].c_str()), 0.0) << csv[i];
	}

	std::vector<std::string> jsonl = splitLines(readTextFile(path("d.jsonl")));
	ASSERT_EQ(jsonl.size(), 3u) << readTextFile(path("d.jsonl"));
	const char *files[] = { "a.png", "b.ppm", "c.JPG" };
	size_t jsonDetections = 0;
	for (int k = 0; k < 3; k++) {
		const std::string &line = jsonl[k];
		std::string prefix = "{\"frame\":" + std::to_string(k + 1) + ",\"method\":\"generic\",\"file\":\"";
		EXPECT_EQ(line.rfind(prefix, 0), 0u) << line;
		EXPECT_NE(line.find(std::string(files[k]) + "\""), std::string::npos) << line;
		size_t ms = line.find(",\"ms\":");
		size_t dets = line.find(",\"detections\":[");
		ASSERT_NE(ms, std::string::npos) << line;
		ASSERT_NE(dets, std::string::npos) << line;
		EXPECT_TRUE(isFixedDecimal(line.substr(ms + 6, dets - ms - 6), 3)) << line;
		EXPECT_EQ(line.substr(line.size() - 2), "]}") << line;
		for (size_t p = line.find("\"score\":"); p != std::string::npos; p = line.find("\"score\":", p + 1))
			jsonDetections++;
	}
	// Both writers see the same detections.
	EXPECT_EQ(jsonDetections, csv.size() - 1);
}

TEST_F(CliRunTest, JsonlToStdoutAndMaxFrames)
{
	ProcessResult r = detect({ "--model", model_, "--jsonl", "-", "--max-frames", "2", "--no-nms",
				   path("frames") });
	ASSERT_TRUE(r.exited) << r.err;
	ASSERT_EQ(r.exitCode, 0) << r.err;
	std::vector<std::string> lines = splitLines(r.out);
	ASSERT_EQ(lines.size(), 2u) << r.out;
	EXPECT_EQ(lines[1].rfind("{\"frame\":2,", 0), 0u) << lines[1];
	// Not quiet: the summary line on stderr counts the frames.
	EXPECT_NE(r.err.find("summary: frames=2 "), std::string::npos) << r.err;
	EXPECT_NE(r.err.find(" method=generic\n"), std::string::npos) << r.err;
	// Without a camera, one line says how to get the calibrated method.
	EXPECT_NE(r.err.find("calped-detect: no camera: the generic method runs; --calib"),
		  std::string::npos)
		<< r.err;
}

TEST_F(CliRunTest, ResizeInsideThePyramidIsTheDefault)
{
	// Upscaling runs inside the pyramid by default, or on the frame with --resize-at frame;
	// below 1 the frame is resized (the pyramid only upscales), and asking for the pyramid
	// there is refused by name.
	for (const std::vector<std::string> &extra :
	     { std::vector<std::string>{}, std::vector<std::string>{ "--resize-at=frame" },
	       std::vector<std::string>{ "--reject-static" } }) {
		std::vector<std::string> args = { "--model", model_, "--resize", "2", "--jsonl", "-",
						  "--quiet", path("frames") };
		args.insert(args.end(), extra.begin(), extra.end());
		ProcessResult r = detect(args);
		ASSERT_TRUE(r.exited) << r.err;
		ASSERT_EQ(r.exitCode, 0) << r.err;
		EXPECT_EQ(splitLines(r.out).size(), 3u) << r.out;
	}
	ProcessResult r = detect({ "--model", model_, "--resize", "0.5", "--quiet", path("frames/a.png") });
	EXPECT_EQ(r.exitCode, 0) << r.err;
	r = detect({ "--model", model_, "--resize", "0.5", "--resize-at", "pyramid", path("frames/a.png") });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--resize-at pyramid"), std::string::npos) << r.err;
	r = detect({ "--model", model_, "--resize-at", "octave", path("frames/a.png") });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--resize-at: expected pyramid or frame, got 'octave'"), std::string::npos) << r.err;
}

TEST_F(CliRunTest, LevelsAreForTheCalibratedMethod)
{
	// --levels chooses the calibrated method's computed levels: with the generic method
	// it is a usage error naming the flag, like --method calibrated without --calib.
	for (const char *levels : { "placed", "toolbox" }) {
		ProcessResult r = detect({ "--model", model_, "--levels", levels, path("frames/a.png") });
		expectOneLineError(r, 2);
		EXPECT_NE(r.err.find("--levels applies to the calibrated method only"), std::string::npos) << r.err;
	}
	ProcessResult r = detect({ "--model", model_, "--method=calibrated", path("frames/a.png") });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--method calibrated needs --calib"), std::string::npos) << r.err;
	r = detect({ "--model", model_, "--no-box-voting", path("frames/a.png") });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--no-box-voting"), std::string::npos) << r.err;
}

TEST_F(CliRunTest, MotRowsWithoutACalibration)
{
	const std::string frame = petsFrame();
	if (frame.empty())
		GTEST_SKIP() << "needs data/pets/frames (scripts/fetch-pets.sh)";
	ProcessResult r = detect({ "--model", model_, "--mot", path("det.txt"), "--csv", path("d.csv"),
				   "--resize", "2", "--quiet", frame });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	const std::vector<std::string> mot = splitLines(readTextFile(path("det.txt")));
	const std::vector<std::string> csv = splitLines(readTextFile(path("d.csv")));
	ASSERT_EQ(mot.size() + 1, csv.size()) << "no header in MOT files";
	ASSERT_FALSE(mot.empty()) << "PETS frame 1 has people";
	for (size_t i = 0; i < mot.size(); i++) {
		const std::vector<std::string> m = splitCommas(mot[i]);
		const std::vector<std::string> c = splitCommas(csv[i + 1]);
		ASSERT_EQ(m.size(), 10u) << mot[i];
		EXPECT_EQ(m[0], c[0]) << mot[i];
		EXPECT_EQ(m[1], "-1") << mot[i];
		for (int k = 0; k < 5; k++)
			EXPECT_EQ(m[2 + k], c[1 + k]) << mot[i];
		EXPECT_EQ(m[7], "-1");
		EXPECT_EQ(m[8], "-1");
		EXPECT_EQ(m[9], "-1");
	}
}

TEST_F(CliRunTest, MinScoreLeavesLowScoresOut)
{
	const std::string frame = petsFrame();
	if (frame.empty())
		GTEST_SKIP() << "needs data/pets/frames (scripts/fetch-pets.sh)";
	ProcessResult all = detect({ "--model", model_, "--csv", path("all.csv"), "--resize", "2", "--no-nms",
				     "--quiet", frame });
	ASSERT_EQ(all.exitCode, 0) << all.err;
	const std::vector<std::string> rows = splitLines(readTextFile(path("all.csv")));
	ASSERT_GT(rows.size(), 2u);
	// The median score as threshold: only rows at or above it stay.
	std::vector<double> scores;
	for (size_t i = 1; i < rows.size(); i++)
		scores.push_back(std::atof(splitCommas(rows[i])[5].c_str()));
	std::vector<double> sorted = scores;
	std::sort(sorted.begin(), sorted.end());
	const double threshold = sorted[sorted.size() / 2];
	size_t expected = 0;
	for (double s : scores)
		expected += s >= threshold;
	char text[32];
	std::snprintf(text, sizeof(text), "%.4f", threshold);
	ProcessResult some = detect({ "--model", model_, "--csv", path("some.csv"), "--resize", "2", "--no-nms",
				      "--min-score=" + std::string(text), "--quiet", frame });
	ASSERT_EQ(some.exitCode, 0) << some.err;
	EXPECT_EQ(splitLines(readTextFile(path("some.csv"))).size() - 1, expected);
	expectOneLineError(detect({ "--model", model_, "--min-score", "high", path("frames") }), 2);
}

TEST_F(CliRunTest, JsonFileNamesAreEscapedAndValidUtf8)
{
	// A control character and a byte that is not UTF-8 in file names: the JSON line stays
	// valid, the control character escaped and the bad byte replaced by U+FFFD.
	fs::create_directory(path("odd"));
	fs::copy_file(path("frames/a.png"), path("odd/a\x01\"q.png"));
	fs::copy_file(path("frames/a.png"), path("odd/b\xff\xc3.png"));
	fs::copy_file(path("frames/a.png"), path("odd/c\xc3\xa9.png")); // valid: kept as is
	ProcessResult r = detect({ "--model", model_, "--jsonl", "-", "--quiet", path("odd") });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	const std::vector<std::string> lines = splitLines(r.out);
	ASSERT_EQ(lines.size(), 3u) << r.out;
	EXPECT_NE(lines[0].find("a\\u0001\\\"q.png\""), std::string::npos) << lines[0];
	EXPECT_NE(lines[1].find("b\xef\xbf\xbd\xef\xbf\xbd.png\""), std::string::npos) << lines[1];
	EXPECT_NE(lines[2].find("c\xc3\xa9.png\""), std::string::npos) << lines[2];
	for (const std::string &l : lines)
		for (unsigned char c : l)
			EXPECT_TRUE(c >= 0x20 && c != 0xff) << "raw byte " << int(c) << " in " << l;
}

TEST_F(CliRunTest, VideoInput)
{
	if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
		GTEST_SKIP() << "ffmpeg is not installed: skipping the video input test";
	// Three frames as a lossless video, then the video and an image as inputs: frames are
	// numbered across them and each JSON record names its input.
	fs::create_directory(path("seq"));
	for (int k = 1; k <= 3; k++)
		ASSERT_TRUE(stbi_write_png(path("seq/00000" + std::to_string(k) + ".png").c_str(), kW, kH, 1,
					   grey_.data(), kW));
	const std::string cmd = "ffmpeg -nostdin -loglevel error -y -framerate 5 -i '" + path("seq/%06d.png") +
				"' -c:v ffv1 '" + path("v.avi") + "'";
	ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
	ProcessResult r = detect({ "--model", model_, "--jsonl", "-", "--csv", path("v.csv"), "--quiet",
				   path("v.avi"), path("frames/b.ppm") });
	ASSERT_TRUE(r.exited) << r.err;
	ASSERT_EQ(r.exitCode, 0) << r.err;
	const std::vector<std::string> lines = splitLines(r.out);
	ASSERT_EQ(lines.size(), 4u) << r.out;
	for (int k = 0; k < 3; k++) {
		EXPECT_EQ(lines[k].rfind("{\"frame\":" + std::to_string(k + 1) + ",", 0), 0u) << lines[k];
		EXPECT_NE(lines[k].find("v.avi\",\"width\":160,\"height\":240,"), std::string::npos) << lines[k];
	}
	EXPECT_NE(lines[3].find("b.ppm\""), std::string::npos) << lines[3];
	// --max-frames stops inside the video.
	r = detect({ "--model", model_, "--jsonl", "-", "--max-frames", "2", "--quiet", path("v.avi") });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(splitLines(r.out).size(), 2u) << r.out;
}

// With a PETS frame and its calibration (skipped without them): --calib alone runs the
// calibrated method, the record says so, and the world fields are filled.
TEST_F(CliRunTest, CalibAloneRunsTheCalibratedMethod)
{
	const std::string calib = petsCalib(), frame = petsFrame();
	if (calib.empty() || frame.empty())
		GTEST_SKIP() << "needs ../shared's View_001.xml and data/pets/frames (scripts/fetch-pets.sh)";
	ProcessResult r = detect({ "--model", model_, "--calib", calib, "--resize", "2", "--jsonl", "-",
				   "--csv", path("c.csv"), "--mot", path("c.txt"), "--quiet", frame });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(r.out.rfind("{\"frame\":1,\"method\":\"calibrated\",", 0), 0u) << r.out;
	const std::vector<std::string> csv = splitLines(readTextFile(path("c.csv")));
	const std::vector<std::string> mot = splitLines(readTextFile(path("c.txt")));
	ASSERT_GT(csv.size(), 1u) << "PETS frame 1 has people";
	ASSERT_EQ(mot.size() + 1, csv.size());
	for (size_t i = 1; i < csv.size(); i++) {
		const std::vector<std::string> f = splitCommas(csv[i]);
		ASSERT_EQ(f.size(), 9u) << csv[i];
		for (int c = 6; c <= 8; c++)
			EXPECT_TRUE(isFixedDecimal(f[c], 3)) << "column " << c << ": " << csv[i];
		const double height = std::atof(f[8].c_str());
		EXPECT_TRUE(height >= 1.4 && height <= 2.2) << csv[i];
		const std::vector<std::string> m = splitCommas(mot[i - 1]);
		EXPECT_EQ(m[7], f[6]);
		EXPECT_EQ(m[8], f[7]);
		EXPECT_EQ(m[9], f[8]);
	}
	// Without --resize: chosen from the camera, and said (PETS people need about 2).
	r = detect({ "--model", model_, "--calib", calib, "--csv", path("a.csv"), frame });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_NE(r.err.find("calped-detect: resize auto: 2 ("), std::string::npos) << r.err;
	EXPECT_EQ(r.err.find("no camera"), std::string::npos) << r.err;
	EXPECT_EQ(readTextFile(path("a.csv")), readTextFile(path("c.csv")));
	// --resize auto needs the camera; --range only means something with it.
	r = detect({ "--model", model_, "--resize", "auto", frame });
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("--resize auto needs a calibration"), std::string::npos) << r.err;
	r = detect({ "--model", model_, "--calib", calib, "--resize", "2", "--range", "20", frame });
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("--range applies to --resize auto only"), std::string::npos) << r.err;
	// --calib auto: the generic method while too few people have been seen, and each record
	// says that no camera estimate is in use yet.
	r = detect({ "--model", model_, "--calib", "auto", "--jsonl", "-", frame });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(r.out.rfind("{\"frame\":1,\"method\":\"generic\",\"camera_estimate\":0,", 0), 0u) << r.out;
	EXPECT_NE(r.err.find("calib auto: the generic method (resize 2) runs until"), std::string::npos)
		<< r.err;
	EXPECT_EQ(r.err.find("no camera"), std::string::npos) << r.err;
	for (const std::vector<std::string> &bad :
	     { std::vector<std::string>{ "--method", "calibrated" }, { "--levels", "toolbox" },
	       { "--resize-at", "frame" } }) {
		std::vector<std::string> args = { "--model", model_, "--calib", "auto" };
		args.insert(args.end(), bad.begin(), bad.end());
		args.push_back(frame);
		r = detect(args);
		EXPECT_EQ(r.exitCode, 2) << bad[0];
		EXPECT_NE(r.err.find("--calib auto"), std::string::npos) << r.err;
	}
	// --method generic with the calibration: the generic method, boxes still placed.
	r = detect({ "--model", model_, "--calib", calib, "--method", "generic", "--resize", "2", "--jsonl", "-",
		     "--quiet", frame });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(r.out.rfind("{\"frame\":1,\"method\":\"generic\",", 0), 0u) << r.out;
	EXPECT_NE(r.out.find("\"world_height\":"), std::string::npos) << r.out;
	// --levels goes with it, and placed levels need the resize inside the pyramid.
	r = detect({ "--model", model_, "--calib", calib, "--levels", "toolbox", "--resize", "1.5",
		     "--resize-at", "frame", "--quiet", frame });
	EXPECT_EQ(r.exitCode, 0) << r.err;
	r = detect({ "--model", model_, "--calib", calib, "--levels", "placed", "--resize", "1.5",
		     "--resize-at", "frame", "--quiet", frame });
	expectOneLineError(r, 2);
	EXPECT_NE(r.err.find("--levels placed"), std::string::npos) << r.err;
}

TEST_F(CliRunTest, OverlaysEveryKthFrameAsRgb)
{
	ProcessResult r = detect({ "--model", model_, "--overlay", path("ov/deep"), "--overlay-every", "2",
				   "--quiet", path("frames") });
	ASSERT_TRUE(r.exited) << r.err;
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_TRUE(fs::exists(path("ov/deep/000001.png")));
	EXPECT_FALSE(fs::exists(path("ov/deep/000002.png")));
	EXPECT_TRUE(fs::exists(path("ov/deep/000003.png")));

	// Frame 1 was grey: the overlay is that image expanded to RGB, plus green boxes.
	int w = 0, h = 0, n = 0;
	stbi_uc *px = stbi_load(path("ov/deep/000001.png").c_str(), &w, &h, &n, 0);
	ASSERT_NE(px, nullptr);
	EXPECT_EQ(w, kW);
	EXPECT_EQ(h, kH);
	EXPECT_EQ(n, 3);
	size_t mismatches = 0;
	for (int i = 0; n == 3 && i < w * h; i++) {
		const stbi_uc *p = px + 3 * i;
		bool green = p[0] == 0 && p[1] == 255 && p[2] == 0;
		if (!green && !(p[0] == grey_[i] && p[1] == grey_[i] && p[2] == grey_[i]))
			mismatches++;
	}
	stbi_image_free(px);
	EXPECT_EQ(mismatches, 0u);
}

// Hostile inputs (issue 19): files that are not regular files are refused by name, not
// waited on (a FIFO) or read for ever (/dev/zero); entries named like frames that are not
// regular files are an error, not silently skipped (later frames would be renumbered); a
// tiny PNG whose header claims 8192x8192 is refused before any detector is sized for it.
TEST_F(CliRunTest, NonRegularFilesAreRefusedByName)
{
	ASSERT_EQ(mkfifo(path("fifo.cpm").c_str(), 0600), 0);
	const auto within = [&](const std::vector<std::string> &args) {
		calped::test::RunningProcess p = calped::test::startProcess(gDetectPath, args, dir_);
		const ProcessResult r = calped::test::waitProcess(p, 60);
		EXPECT_FALSE(r.hung) << "hung";
		return r;
	};
	ProcessResult r = within({ "--model", path("fifo.cpm"), path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("model " + path("fifo.cpm") + ": is a FIFO"), std::string::npos) << r.err;
	r = within({ "--model", "/dev/zero", path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("/dev/zero: is a device"), std::string::npos) << r.err;
	r = within({ "--model", model_, "--calib", path("fifo.cpm"), path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("is a FIFO"), std::string::npos) << r.err;

	for (const char *kind : { "fifo", "folder", "dangling" }) {
		const std::string entry = path("frames/b2.png");
		if (std::string(kind) == "fifo")
			ASSERT_EQ(mkfifo(entry.c_str(), 0600), 0);
		else if (std::string(kind) == "folder")
			fs::create_directory(entry);
		else
			fs::create_symlink(path("nowhere.png"), entry);
		r = within({ "--model", model_, "--quiet", path("frames") });
		expectOneLineError(r, 1);
		EXPECT_NE(r.err.find("b2.png is named like a frame but is a"), std::string::npos) << kind << ": " << r.err;
		std::error_code ec;
		fs::remove_all(entry, ec);
	}
}

TEST_F(CliRunTest, HugeImageHeaderIsRefusedBeforeSizingTheDetector)
{
	// A 1x1 PNG whose header (IHDR, bytes 16-23) then says 8192x8192: stb reads the size
	// from the header alone.
	const uint8_t pixel[3] = { 1, 2, 3 };
	ASSERT_TRUE(stbi_write_png(path("huge.png").c_str(), 1, 1, 3, pixel, 3));
	std::fstream f(path("huge.png"), std::ios::in | std::ios::out | std::ios::binary);
	const char size[8] = { 0, 0, 0x20, 0, 0, 0, 0x20, 0 };
	f.seekp(16);
	f.write(size, 8);
	f.close();
	ProcessResult r = detect({ "--model", model_, "--resize", "2", path("huge.png") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("8192x8192 frames at resize 2"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("over the memory budget of 1.00 GiB"), std::string::npos) << r.err;
}

// Outputs are written beside their name and renamed on success: a run that fails half-way
// leaves the earlier file as it was, and calped-convert never replaces what is not a file.
TEST_F(CliRunTest, AFailedRunLeavesTheEarlierOutputs)
{
	// A PNG whose header is sound (it passes the probe) but whose pixel data is damaged.
	ASSERT_TRUE(stbi_write_png(path("frames/d.png").c_str(), kW, kH, 1, grey_.data(), kW));
	std::fstream f(path("frames/d.png"), std::ios::in | std::ios::out | std::ios::binary);
	f.seekp(60);
	f.write(std::string(64, '\x55').data(), 64);
	f.close();
	std::ofstream(path("d.csv")) << "the earlier result\n";
	const ProcessResult r = detect({ "--model", model_, "--csv", path("d.csv"), "--quiet", path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("d.png"), std::string::npos) << r.err;
	EXPECT_EQ(readTextFile(path("d.csv")), "the earlier result\n");
	for (const auto &entry : fs::directory_iterator(dir_))
		EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();

	// calped-convert onto a FIFO (a device node in the issue): refused, the FIFO stays.
	const char *shared = std::getenv("CALPED_SHARED_DIR");
	const std::string mat = std::string(shared ? shared : "../shared") + "/models/dollar-toolbox/AcfInriaDetector.mat";
	ASSERT_EQ(mkfifo(path("out.cpm").c_str(), 0600), 0);
	const ProcessResult c = runProcess(gConvertPath, { mat, path("out.cpm") }, dir_);
	EXPECT_EQ(c.exitCode, 1) << c.err;
	EXPECT_NE(c.err.find("exists and is not a regular file (not replaced)"), std::string::npos) << c.err;
	EXPECT_TRUE(fs::is_fifo(path("out.cpm")));
}

TEST_F(CliRunTest, UnwritableOutputIsARuntimeError)
{
	ProcessResult r = detect({ "--model", model_, "--csv", path("no/such/dir/d.csv"), path("frames") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("d.csv"), std::string::npos) << r.err;
}

} // namespace

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	for (int i = 1; i < argc; i++) {
		std::string a = argv[i];
		if (a.rfind("--detect=", 0) == 0)
			gDetectPath = a.substr(9);
		else if (a.rfind("--convert=", 0) == 0)
			gConvertPath = a.substr(10);
	}
	int rc = RUN_ALL_TESTS();
	calped::test::removeConvertedModel();
	return rc;
}
