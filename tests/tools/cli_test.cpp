// SPDX-License-Identifier: BSD-2-Clause
// calped-detect as a black box: exit codes, one-line errors, and the shape of its outputs.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "process.h"

namespace fs = std::filesystem;
using calped::test::ProcessResult;
using calped::test::readTextFile;
using calped::test::runProcess;
using calped::test::splitLines;

// Set by main() from the command line meson passes.
std::string gDetectPath;
std::string gConvertPath;
// Scratch folder for the converted model, removed by main() at the end.
std::string gModelDir;

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
	for (const char *flag : { "--resize-in-pyramid=1", "--reject-static=yes", "--no-nms=0" }) {
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

// Converts Dollár's INRIA model once per test binary; empty with a reason when it cannot.
const std::string &convertedModel(std::string &skipReason)
{
	static std::string model;
	static std::string reason;
	static bool tried = false;
	if (!tried) {
		tried = true;
		const char *shared = std::getenv("CALPED_SHARED_DIR");
		std::string mat = std::string(shared ? shared : "../shared") +
				  "/models/dollar-toolbox/AcfInriaDetector.mat";
		if (!fs::exists(mat)) {
			reason = "no " + mat + " (../shared models absent)";
		} else if (gConvertPath.empty() || !fs::exists(gConvertPath)) {
			reason = "calped-convert is not built (" + gConvertPath + ")";
		} else {
			std::string pattern = (fs::temp_directory_path() / "calped-cli-model-XXXXXX").string();
			std::vector<char> buf(pattern.begin(), pattern.end());
			buf.push_back('\0');
			if (!mkdtemp(buf.data()))
				throw std::runtime_error("mkdtemp failed");
			gModelDir = buf.data();
			std::string out = gModelDir + "/AcfInriaDetector.cpm";
			ProcessResult r = runProcess(gConvertPath, { mat, out }, gModelDir);
			if (!r.exited || r.exitCode != 0 || !fs::exists(out))
				reason = "FAIL: calped-convert " + mat + " failed: " + r.err;
			else
				model = out;
		}
	}
	skipReason = reason;
	return model;
}

class CliRunTest : public CliTest
{
protected:
	void SetUp() override
	{
		CliTest::SetUp();
		if (HasFatalFailure())
			return;
		std::string reason;
		model_ = convertedModel(reason);
		if (model_.empty()) {
			// A converter that exists but fails is a failure, not a reason to skip.
			ASSERT_NE(reason.rfind("FAIL: ", 0), 0u) << reason;
			GTEST_SKIP() << reason;
		}

		// Three frames in name order: grey PNG, colour PPM, colour JPEG; plus things to ignore.
		fs::create_directory(path("frames"));
		fs::create_directory(path("frames/sub.png"));
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
	EXPECT_EQ(csv[0], "frame,x,y,w,h,score");
	for (size_t i = 1; i < csv.size(); i++) {
		std::vector<std::string> f = splitCommas(csv[i]);
		ASSERT_EQ(f.size(), 6u) << "row " << i << ": " << csv[i];
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
		std::string prefix = "{\"frame\":" + std::to_string(k + 1) + ",\"file\":\"";
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
}

TEST_F(CliRunTest, ResizeInsideThePyramid)
{
	// Upscaling inside the pyramid runs; downscaling there is refused by name.
	ProcessResult r = detect({ "--model", model_, "--resize", "2", "--resize-in-pyramid", "--jsonl", "-",
				   "--quiet", path("frames") });
	ASSERT_TRUE(r.exited) << r.err;
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(splitLines(r.out).size(), 3u) << r.out;
	// With static rejection too: three frames are all inside its warm-up.
	r = detect({ "--model", model_, "--resize", "2", "--resize-in-pyramid", "--reject-static",
		     "--jsonl", "-", "--quiet", path("frames") });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(splitLines(r.out).size(), 3u) << r.out;
	r = detect({ "--model", model_, "--resize", "0.5", "--resize-in-pyramid", path("frames/a.png") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("pyramid"), std::string::npos) << r.err;
}

TEST_F(CliRunTest, PlacedPyramidIsForTheCalibratedMethod)
{
	// --calibrated-pyramid places computed levels from a calibration's plan: without the
	// calibrated method it is refused by name, with a one-line error.
	ProcessResult r = detect({ "--model", model_, "--calibrated-pyramid", path("frames/a.png") });
	expectOneLineError(r, 1);
	EXPECT_NE(r.err.find("method is generic"), std::string::npos) << r.err;
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
	if (!gModelDir.empty()) {
		std::error_code ec;
		fs::remove_all(gModelDir, ec);
	}
	return rc;
}
