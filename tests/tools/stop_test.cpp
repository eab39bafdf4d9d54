// SPDX-License-Identifier: BSD-2-Clause
// Hard stops, black box: SIGTERM/SIGINT in the middle of a run leaves complete output lines
// up to the last frame processed and exit status 128 + the signal, in calped-detect,
// calped-eval and the live loop (calped-play); a damaged video ends with a clear error,
// not a hang. The videos are made here with ffmpeg (skipped without it).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "process.h"
#include "test_model.h"

namespace fs = std::filesystem;
using calped::test::ProcessResult;
using calped::test::readTextFile;
using calped::test::RunningProcess;
using calped::test::splitLines;
using calped::test::startProcess;
using calped::test::waitProcess;

std::string gDetectPath, gEvalPath, gPlayPath, gConvertPath;

namespace {

constexpr int kFrames = 1500; // far more than a run gets through before the signal

// Polls `done` every 20 ms for at most `seconds`.
bool waitFor(const std::function<bool()> &done, double seconds)
{
	const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(seconds * 1000));
	while (std::chrono::steady_clock::now() < end) {
		if (done())
			return true;
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
	return false;
}

bool nonEmptyFile(const std::string &path)
{
	std::error_code ec;
	return fs::exists(path, ec) && fs::file_size(path, ec) > 0;
}

// An output file is written as PATH.tmp-... and renamed at the end: true once that
// temporary file has data (the run is under way).
bool outputGrowing(const std::string &path)
{
	const fs::path p(path);
	std::error_code ec;
	for (fs::directory_iterator it(p.parent_path(), ec), end; !ec && it != end; it.increment(ec))
		if (it->path().filename().string().rfind(p.filename().string() + ".tmp-", 0) == 0 &&
		    it->file_size(ec) > 0)
			return true;
	return false;
}

// Every line is a whole JSON frame record, frames 1, 2, ... in order, the file ends with
// a line break; returns the number of records.
size_t expectCompleteJsonl(const std::string &text, const std::string &what)
{
	EXPECT_TRUE(text.empty() || text.back() == '\n') << what << " ends inside a line";
	const std::vector<std::string> lines = splitLines(text);
	for (size_t i = 0; i < lines.size(); i++) {
		EXPECT_EQ(lines[i].rfind("{\"frame\":" + std::to_string(i + 1) + ",", 0), 0u) << what << ": " << lines[i];
		EXPECT_NE(lines[i].find("\"detections\":["), std::string::npos) << what << ": " << lines[i];
		EXPECT_EQ(lines[i].back(), '}') << what << ": " << lines[i];
	}
	return lines.size();
}

// CSV or MOT rows: `fields` comma-separated fields each, the file ends with a line break.
void expectCompleteRows(const std::string &text, size_t fields, const std::string &what)
{
	EXPECT_TRUE(text.empty() || text.back() == '\n') << what << " ends inside a line";
	for (const std::string &line : splitLines(text)) {
		size_t commas = 0;
		for (char c : line)
			commas += c == ',';
		EXPECT_EQ(commas + 1, fields) << what << ": " << line;
	}
}

class StopTest : public ::testing::Test
{
protected:
	static void SetUpTestSuite()
	{
		const char *tmp = std::getenv("TMPDIR");
		std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/calped-stop-XXXXXX";
		std::vector<char> buf(pattern.begin(), pattern.end());
		buf.push_back('\0');
		if (mkdtemp(buf.data()))
			dir_ = buf.data();
		if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) {
			skip_ = "ffmpeg is not installed: skipping the stop tests (they need a video)";
			return;
		}
		model_ = calped::test::convertedModel(gConvertPath, skip_);
		if (model_.empty())
			return;
		// A test pattern video, and a damaged copy of a shorter one: bytes in its middle
		// half overwritten and its tail cut off.
		const std::string make = "ffmpeg -nostdin -loglevel error -y -f lavfi -i testsrc=size=320x240:rate=25 -frames:v ";
		const std::string cmd = make + std::to_string(kFrames) + " -c:v mpeg4 -q:v 5 '" + dir_ + "/long.avi' && " +
					make + "600 -c:v mpeg4 -q:v 5 '" + dir_ + "/short.avi'";
		if (std::system(cmd.c_str()) != 0) {
			skip_ = "FAIL: " + cmd;
			return;
		}
		std::ifstream in(dir_ + "/short.avi", std::ios::binary);
		std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
		std::mt19937 rng(19);
		for (size_t i = bytes.size() / 4; i < bytes.size() * 3 / 4; i += 97)
			bytes[i] = static_cast<char>(rng() & 0xff);
		std::ofstream(dir_ + "/damaged.avi", std::ios::binary)
			.write(bytes.data(), static_cast<std::streamsize>(bytes.size() * 9 / 10));
	}
	static void TearDownTestSuite()
	{
		std::error_code ec;
		if (!dir_.empty())
			fs::remove_all(dir_, ec);
	}
	void SetUp() override
	{
		ASSERT_FALSE(dir_.empty()) << "mkdtemp failed";
		ASSERT_NE(skip_.rfind("FAIL: ", 0), 0u) << skip_;
		if (!skip_.empty())
			GTEST_SKIP() << skip_;
		scratch_ = dir_ + "/" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
		fs::create_directories(scratch_);
	}
	std::string path(const std::string &name) const { return scratch_ + "/" + name; }

	// Starts the program, sends `signal` once `started` holds, and expects it to end
	// within 30 s with 128 + signal.
	ProcessResult stopMidRun(const std::string &program, const std::vector<std::string> &args,
				 const std::function<bool()> &started, int signal)
	{
		RunningProcess p = startProcess(program, args, scratch_);
		EXPECT_TRUE(waitFor(started, 120)) << program << " produced no output in 120 s";
		kill(p.pid, signal);
		const ProcessResult r = waitProcess(p, 30);
		EXPECT_FALSE(r.hung) << program << " still running 30 s after the signal";
		EXPECT_TRUE(r.exited) << program << " killed by signal " << r.signal << "\n" << r.err;
		EXPECT_EQ(r.exitCode, 128 + signal) << r.err;
		return r;
	}

	static std::string dir_, model_, skip_;
	std::string scratch_;
};

std::string StopTest::dir_, StopTest::model_, StopTest::skip_;

TEST_F(StopTest, DetectFinishesItsLinesOnSigterm)
{
	const ProcessResult r = stopMidRun(
		gDetectPath,
		{ "--model", model_, "--csv", path("d.csv"), "--mot", path("d.mot"), "--jsonl", path("d.jsonl"),
		  "--quiet", dir_ + "/long.avi" },
		[&] { return outputGrowing(path("d.jsonl")); }, SIGTERM);
	const size_t frames = expectCompleteJsonl(readTextFile(path("d.jsonl")), "d.jsonl");
	EXPECT_GT(frames, 0u);
	EXPECT_LT(frames, static_cast<size_t>(kFrames)) << "the run ended before the signal";
	const std::string csv = readTextFile(path("d.csv"));
	ASSERT_EQ(csv.rfind("frame,x,y,w,h,score,ground_x,ground_y,world_height\n", 0), 0u) << csv;
	expectCompleteRows(csv, 9, "d.csv");
	expectCompleteRows(readTextFile(path("d.mot")), 10, "d.mot");
}

TEST_F(StopTest, PlayFinishesItsLinesOnSigint)
{
	if (gPlayPath.empty())
		GTEST_SKIP() << "calped-play is not built";
	const ProcessResult r = stopMidRun(gPlayPath, { "--model", model_, "--input", dir_ + "/long.avi", "--quiet" },
					   [&] { return nonEmptyFile(scratch_ + "/.stdout"); }, SIGINT);
	const size_t frames = expectCompleteJsonl(r.out, "calped-play's output");
	EXPECT_GT(frames, 0u);
	EXPECT_LT(frames, static_cast<size_t>(kFrames)) << "the run ended before the signal";
}

TEST_F(StopTest, EvalFinishesItsLinesOnSigterm)
{
	std::ofstream(path("gt.txt")) << "1,1,10,10,40,100,1,-1,-1,-1\n";
	const ProcessResult r = stopMidRun(
		gEvalPath,
		{ "--video", dir_ + "/long.avi", "--gt", path("gt.txt"), "--model", model_, "--frames-jsonl",
		  path("runs"), "--json", path("score.json"), "--quiet" },
		[&] { return outputGrowing(path("runs/generic_r1.0.jsonl")); }, SIGTERM);
	const size_t frames = expectCompleteJsonl(readTextFile(path("runs/generic_r1.0.jsonl")), "the run's JSONL");
	EXPECT_GT(frames, 0u);
	EXPECT_LT(frames, static_cast<size_t>(kFrames)) << "the run ended before the signal";
	EXPECT_FALSE(fs::exists(path("score.json"))) << "no score from a stopped run";
}

// One error line naming the video and ffmpeg's complaint, within a bounded time; the
// frames before it keep complete lines.
void expectDamagedVideoError(const ProcessResult &r, const std::string &program)
{
	ASSERT_FALSE(r.hung) << program << " hung on the damaged video";
	ASSERT_TRUE(r.exited) << program << " killed by signal " << r.signal;
	EXPECT_EQ(r.exitCode, 1) << r.err;
	const std::vector<std::string> lines = splitLines(r.err);
	ASSERT_EQ(lines.size(), 1u) << r.err;
	EXPECT_EQ(lines[0].rfind(program + ": ", 0), 0u) << lines[0];
	EXPECT_NE(lines[0].find("damaged.avi"), std::string::npos) << lines[0];
	EXPECT_NE(lines[0].find("ffmpeg"), std::string::npos) << lines[0];
}

TEST_F(StopTest, DamagedVideoIsAClearErrorNotAHang)
{
	RunningProcess p = startProcess(gDetectPath, { "--model", model_, "--jsonl", path("d.jsonl"), "--quiet",
						       dir_ + "/damaged.avi" }, scratch_);
	ProcessResult r = waitProcess(p, 120);
	expectDamagedVideoError(r, "calped-detect");
	const size_t frames = expectCompleteJsonl(readTextFile(path("d.jsonl")), "d.jsonl");
	EXPECT_LT(frames, 600u);

	if (gPlayPath.empty())
		return; // calped-play is not built
	p = startProcess(gPlayPath, { "--model", model_, "--input", dir_ + "/damaged.avi", "--quiet" }, scratch_);
	r = waitProcess(p, 120);
	expectDamagedVideoError(r, "calped-play");
	expectCompleteJsonl(r.out, "calped-play's output");
}

// No complete frame for --frame-timeout seconds (a camera that only sends damaged frames, here
// a file paced at one frame per 100 s): a clear error after that time, not a run for ever.
TEST_F(StopTest, LiveLoopGivesUpAfterTheFrameTimeout)
{
	if (gPlayPath.empty())
		GTEST_SKIP() << "calped-play is not built";
	const auto start = std::chrono::steady_clock::now();
	RunningProcess p = startProcess(gPlayPath, { "--model", model_, "--input", dir_ + "/long.avi", "--fps", "0.01",
						     "--timeout", "100", "--frame-timeout", "4", "--quiet" },
					scratch_);
	const ProcessResult r = waitProcess(p, 60);
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	ASSERT_FALSE(r.hung);
	ASSERT_TRUE(r.exited) << r.signal;
	EXPECT_EQ(r.exitCode, 1) << r.err;
	EXPECT_GE(seconds, 4.0);
	const std::vector<std::string> lines = splitLines(r.err);
	ASSERT_EQ(lines.size(), 1u) << r.err;
	EXPECT_NE(lines[0].find("no complete frame for 4."), std::string::npos) << lines[0];
	EXPECT_NE(lines[0].find("--frame-timeout 4"), std::string::npos) << lines[0];
	// Frame 1 comes as soon as ffmpeg starts; 4 s leaves room for a loaded machine's start-up
	// (with 1 s, ffmpeg's start under load was already past the timeout).
	EXPECT_EQ(expectCompleteJsonl(r.out, "calped-play's output"), 1u);
}

} // namespace

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		for (auto [flag, target] : { std::pair<const char *, std::string *>{ "--detect=", &gDetectPath },
					     { "--eval=", &gEvalPath }, { "--play=", &gPlayPath },
					     { "--convert=", &gConvertPath } })
			if (a.rfind(flag, 0) == 0)
				*target = a.substr(std::string(flag).size());
	}
	const int rc = RUN_ALL_TESTS();
	calped::test::removeConvertedModel();
	return rc;
}
