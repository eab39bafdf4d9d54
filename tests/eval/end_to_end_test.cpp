// SPDX-License-Identifier: BSD-2-Clause
// calped-eval as a black box: usage and input errors without data, then one run over the
// first 5 PETS frames (skipped without ../shared and data/pets/frames).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "ground_truth.h"
#include "test_data.h"
#include "test_paths.h"

namespace calped::eval_tool {
namespace {

namespace fs = std::filesystem;

struct Result {
	int exitCode = -1;
	std::string out, err;
};

std::string quote(const std::string &s)
{
	std::string q = "'";
	for (char c : s)
		q += c == '\'' ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

std::string slurp(const std::string &path)
{
	std::ifstream f(path);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

class EvalCli : public ::testing::Test
{
protected:
	void SetUp() override
	{
		exe_ = test::envOr("CALPED_EVAL", "");
		if (exe_.empty())
			GTEST_SKIP() << "CALPED_EVAL is not set";
		dir_ = fs::path(test::envOr("CALPED_BUILD_DIR", ".")) /
		       ("eval-e2e-" + std::to_string(getpid()) + "-" +
			::testing::UnitTest::GetInstance()->current_test_info()->name());
		fs::remove_all(dir_);
		fs::create_directories(dir_);
	}
	void TearDown() override
	{
		if (!dir_.empty() && !HasFailure())
			fs::remove_all(dir_);
	}

	Result run(const std::string &args)
	{
		const std::string out = (dir_ / "stdout.txt").string();
		const std::string err = (dir_ / "stderr.txt").string();
		const std::string cmd = quote(exe_) + " " + args + " >" + quote(out) + " 2>" + quote(err);
		const int status = std::system(cmd.c_str());
		Result r;
		r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
		r.out = slurp(out);
		r.err = slurp(err);
		return r;
	}

	std::string exe_;
	fs::path dir_;
};

TEST_F(EvalCli, UnknownMethodIsAUsageError)
{
	const Result r = run("--frames x --model y --gt z --methods fastest");
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("unknown method 'fastest' (known: generic, calibrated, calibrated-static)"), std::string::npos)
		<< r.err;
}

TEST_F(EvalCli, MalformedGroundTruthNamesFileAndLine)
{
	const std::string gt = test::dataPath("mot_bad_number.txt");
	const Result r = run("--frames x --model y --gt " + quote(gt));
	EXPECT_EQ(r.exitCode, 1);
	EXPECT_NE(r.err.find("calped-eval: " + gt + ":2: "), std::string::npos) << r.err;
}

TEST_F(EvalCli, CalibratedWithoutCalibrationIsNamedAndSkipped)
{
	// Nothing is loaded when every method is skipped, so no frames or model are needed.
	const Result r = run("--frames x --model y --methods calibrated --gt " +
			     quote(test::dataPath("mot_small.txt")));
	EXPECT_EQ(r.exitCode, 0) << r.err;
	EXPECT_NE(r.err.find("method 'calibrated' needs --calib FILE; skipped"), std::string::npos) << r.err;
}

TEST_F(EvalCli, ScoreOnlyNeedsTheFrameCount)
{
	const Result r = run("--score-only a.csv --gt " + quote(test::dataPath("mot_small.txt")));
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("--num-frames"), std::string::npos) << r.err;
}

// Value of `"key": number` in the n-th (0-based) object of calped-eval's JSON.
double jsonValue(const std::string &json, int n, const std::string &key);

TEST_F(EvalCli, ScoreOnlyMaxFramesScoresTheFirstFrames)
{
	// Detections on frames 1-3 of a 3-frame sequence; --max-frames 2 scores frames 1-2.
	const fs::path csv = dir_ / "run.csv";
	std::ofstream(csv) << "frame,x,y,w,h,score\n1,100,200,30,80,50\n2,105,201,30,80,40\n"
			      "3,400,100,30,80,30\n";
	const std::string gt = quote(test::dataPath("mot_small.txt"));
	const fs::path json = dir_ / "scored.json";
	Result r = run("--score-only " + quote(csv.string()) + " --num-frames 3 --max-frames 2 --gt " + gt +
		       " --json " + quote(json.string()));
	ASSERT_EQ(r.exitCode, 0) << r.err;
	std::string text = slurp(json.string());
	EXPECT_EQ(jsonValue(text, 0, "frames"), 2.0) << text;
	EXPECT_EQ(jsonValue(text, 0, "detections"), 2.0) << text;
	r = run("--score-only " + quote(csv.string()) + " --num-frames 3 --gt " + gt + " --json " +
		quote(json.string()));
	ASSERT_EQ(r.exitCode, 0) << r.err;
	text = slurp(json.string());
	EXPECT_EQ(jsonValue(text, 0, "frames"), 3.0) << text;
	EXPECT_EQ(jsonValue(text, 0, "detections"), 3.0) << text;
	// A row beyond the frames the CSV covers is still an error.
	r = run("--score-only " + quote(csv.string()) + " --num-frames 2 --gt " + gt);
	EXPECT_EQ(r.exitCode, 1) << r.err;
	EXPECT_NE(r.err.find("run.csv:4"), std::string::npos) << r.err;
}

double jsonValue(const std::string &json, int n, const std::string &key)
{
	size_t pos = 0;
	for (int i = 0; i <= n; i++) {
		pos = json.find("\"method\"", i ? pos + 1 : 0);
		if (pos == std::string::npos)
			return NAN;
	}
	const size_t k = json.find("\"" + key + "\": ", pos);
	if (k == std::string::npos)
		return NAN;
	return std::atof(json.c_str() + k + key.size() + 4);
}

TEST_F(EvalCli, FivePetsFrames)
{
	const std::string shared = calped::test::sharedDir();
	const std::string convert = test::envOr("CALPED_CONVERT", "");
	if (shared.empty() || calped::test::petsFrame(5).empty() || convert.empty())
		GTEST_SKIP() << "needs ../shared, data/pets/frames (scripts/fetch-pets.sh) and calped-convert";
	if (!cvmlSupported()) // the same harness library as calped-eval
		GTEST_SKIP() << "built without expat: the PETS ground truth is CVML XML";
	const std::string gt = shared + "/data/pets2009-s2l1/PETS2009-S2L1.xml";
	// A blob of our own: converting takes milliseconds, and sharing one file with other
	// tests running at the same time could let one read it half written.
	const std::string model = (dir_ / "inria.cpm").string();
	const std::string cmd = quote(convert) + " " +
				quote(shared + "/models/dollar-toolbox/AcfInriaDetector.mat") + " " + quote(model) +
				" >/dev/null";
	ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

	// A folder holding only the first 5 frames is scored on those 5.
	const fs::path frames = dir_ / "frames";
	fs::create_directories(frames);
	for (int k = 1; k <= 5; k++)
		fs::create_symlink(fs::absolute(calped::test::petsFrame(k)), frames / fs::path(calped::test::petsFrame(k)).filename());

	const std::string calib = shared + "/data/pets2009-s2l1/View_001.xml";
	const fs::path json = dir_ / "runs.json";
	const Result r = run("--frames " + quote(frames.string()) + " --gt " + quote(gt) + " --model " +
			     quote(model) + " --calib " + quote(calib) +
			     " --methods generic,calibrated --resizes 1.0,2.0 --jobs 2" +
			     " --json " + quote(json.string()) + " --dets " + quote((dir_ / "dets").string()) +
			     " --overlays " + quote((dir_ / "ov").string()) + " --overlay-frames 1,5,9" +
			     " --frames-jsonl " + quote((dir_ / "jsonl").string()));
	ASSERT_EQ(r.exitCode, 0) << r.err;
	// The thesis's Table 4.1 pyramid and CApF for PETS at resize 2 (Dollár's scale rules).
	EXPECT_NE(r.out.find("| generic | 2.0 | 29 (4) | 570135 |"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("| generic | 1.0 |"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("| calibrated | 2.0 |"), std::string::npos) << r.out;

	// Runs come ordered by resize, then method.
	const std::string text = slurp(json.string());
	const double resizes[] = { 1.0, 1.0, 2.0, 2.0 };
	for (int i = 0; i < 4; i++) {
		EXPECT_EQ(jsonValue(text, i, "resize"), resizes[i]) << text;
		EXPECT_EQ(jsonValue(text, i, "frames"), 5) << text;
		EXPECT_EQ(jsonValue(text, i, "gt_boxes"), 15) << text; // annotation frames 0-4
		EXPECT_GT(jsonValue(text, i, "peak_rss_kib"), 1000) << text;
		EXPECT_GT(jsonValue(text, i, "ms_per_frame"), 0) << text;
	}
	EXPECT_NE(text.find("\"method\": \"calibrated\""), std::string::npos) << text;
	EXPECT_EQ(jsonValue(text, 2, "scales"), 29);
	EXPECT_EQ(jsonValue(text, 2, "octaves"), 4);
	EXPECT_EQ(jsonValue(text, 2, "capf"), 570135);
	// People in PETS are 53-153 pixels tall; upscaled 2x the INRIA model finds most of them.
	EXPECT_GE(jsonValue(text, 2, "tpr"), 0.8) << text;
	// The calibrated mode looks at fewer scales and far fewer windows.
	EXPECT_LT(jsonValue(text, 3, "scales"), jsonValue(text, 2, "scales"));
	EXPECT_LT(jsonValue(text, 3, "capf"), jsonValue(text, 2, "capf") / 4);

	EXPECT_TRUE(fs::exists(dir_ / "dets" / "generic_r1.0.csv"));
	// Overlays are named as every program names them, in a folder per run.
	EXPECT_TRUE(fs::exists(dir_ / "ov" / "generic_r2.0" / "000001.png"));
	EXPECT_TRUE(fs::exists(dir_ / "ov" / "generic_r2.0" / "000005.png"));
	EXPECT_FALSE(fs::exists(dir_ / "ov" / "generic_r2.0" / "000009.png")); // beyond the 5 frames
	// The JSON frame records of calped-detect, one per frame, saying which method ran.
	const std::string records = slurp((dir_ / "jsonl" / "calibrated_r2.0.jsonl").string());
	EXPECT_EQ(std::count(records.begin(), records.end(), '\n'), 5) << records;
	EXPECT_EQ(records.rfind("{\"frame\":1,\"method\":\"calibrated\",\"file\":", 0), 0u) << records;
	EXPECT_NE(records.find("\"world_height\":"), std::string::npos) << records;

	// Scoring the written detections reproduces the run's accuracy exactly.
	const fs::path scored = dir_ / "scored.json";
	const Result s = run("--score-only " + quote((dir_ / "dets" / "generic_r2.0.csv").string()) +
			     " --frames " + quote(frames.string()) + " --gt " + quote(gt) + " --json " +
			     quote(scored.string()));
	ASSERT_EQ(s.exitCode, 0) << s.err;
	const std::string again = slurp(scored.string());
	for (const char *key : { "tpr", "tpr_any", "fppf", "log_avg_miss_rate", "detections" })
		EXPECT_EQ(jsonValue(again, 0, key), jsonValue(text, 2, key)) << key;
	EXPECT_EQ(jsonValue(again, 0, "resize"), 2.0); // from the file name
}

} // namespace
} // namespace calped::eval_tool
