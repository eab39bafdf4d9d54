// SPDX-License-Identifier: BSD-2-Clause
// The live examples as black boxes: calped-play (always) and calped-aravis (when built,
// against the GigE Vision simulator). JSON lines on stdout, stats on stderr, --frames N,
// the end of a finite source, SIGTERM, and exit statuses.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fcntl.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

#include <stb_image_write.h>

#include "fake_gv_camera.h"
#include "process.h"
#include "test_data.h"

extern char **environ;

namespace fs = std::filesystem;
using calped::test::ProcessResult;
using calped::test::runProcess;
using calped::test::splitLines;

namespace {

std::string gPlay, gAravis; // set by main() from meson's arguments

class LiveExample : public ::testing::Test
{
protected:
	void SetUp() override
	{
		char tmpl[] = "/tmp/calped-live-XXXXXX";
		ASSERT_NE(mkdtemp(tmpl), nullptr);
		dir_ = tmpl;
		fs::create_directory(dir_ + "/frames");
		// Four 96x160 noise frames: big enough for the model window, no people in them.
		std::vector<uint8_t> px(96 * 160 * 3);
		for (int k = 0; k < 4; k++) {
			for (size_t i = 0; i < px.size(); i++)
				px[i] = static_cast<uint8_t>((i * 2654435761u + k * 97u) >> 13);
			const std::string name = dir_ + "/frames/" + std::to_string(k) + ".png";
			ASSERT_TRUE(stbi_write_png(name.c_str(), 96, 160, 3, px.data(), 96 * 3));
		}
		model_ = calped::test::inriaModelBlob();
	}
	void TearDown() override
	{
		std::error_code ec;
		fs::remove_all(dir_, ec);
	}
	std::string dir_, model_;
};

// Every line is one complete JSON object with the fields of docs/ports.md.
void expectJsonLines(const std::vector<std::string> &lines)
{
	for (const std::string &l : lines) {
		EXPECT_EQ(l.rfind("{\"frame\":", 0), 0u) << l;
		// calped-detect's record: which method ran, then the live source's timestamp.
		EXPECT_NE(l.find(",\"method\":\"generic\",\"timestamp_ns\":"), std::string::npos) << l;
		EXPECT_NE(l.find(",\"width\":"), std::string::npos) << l;
		EXPECT_NE(l.find("\"detections\":["), std::string::npos) << l;
		EXPECT_EQ(l.substr(l.size() - 2), "]}") << l;
	}
}

} // namespace

TEST_F(LiveExample, PlayStopsAfterFramesWithStatusZero)
{
	if (model_.empty())
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	const ProcessResult r = runProcess(
		gPlay, { "--input", dir_ + "/frames", "--model", model_, "--loop", "--frames", "6" }, dir_);
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0) << r.err;
	const auto lines = splitLines(r.out);
	ASSERT_EQ(lines.size(), 6u);
	expectJsonLines(lines);
	EXPECT_EQ(lines[5].rfind("{\"frame\":6,", 0), 0u) << lines[5];
	EXPECT_NE(r.err.find("processed 6, delivered 6"), std::string::npos) << r.err;
}

TEST_F(LiveExample, PlayEndsWithTheSequence)
{
	if (model_.empty())
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	const ProcessResult r =
		runProcess(gPlay, { "--input", dir_ + "/frames", "--model", model_, "--quiet" }, dir_);
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(splitLines(r.out).size(), 4u);
	EXPECT_TRUE(r.err.empty()) << r.err;
}

// Overlays are named as calped-detect names them: DIR/NNNNNN.png by frame number.
TEST_F(LiveExample, PlayOverlaysAreNamedLikeCalpedDetects)
{
	if (model_.empty())
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	const ProcessResult r = runProcess(gPlay, { "--input=" + dir_ + "/frames", "--model=" + model_,
						    "--overlay=" + dir_ + "/ov", "--overlay-every=2", "--quiet" },
					   dir_);
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0) << r.err;
	EXPECT_TRUE(fs::exists(dir_ + "/ov/000001.png"));
	EXPECT_FALSE(fs::exists(dir_ + "/ov/000002.png"));
	EXPECT_TRUE(fs::exists(dir_ + "/ov/000003.png"));
}

TEST_F(LiveExample, UsageAndRuntimeErrors)
{
	ProcessResult r = runProcess(gPlay, { "--input", dir_ + "/frames", "--bogus" }, dir_);
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("unknown option '--bogus'"), std::string::npos) << r.err;
	r = runProcess(gPlay, { "--input", dir_ + "/frames" }, dir_);
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_NE(r.err.find("missing --model"), std::string::npos) << r.err;
	r = runProcess(gPlay, { "--input", dir_ + "/frames", "--model", dir_ + "/none.cpm" }, dir_);
	EXPECT_EQ(r.exitCode, 1);
	EXPECT_NE(r.err.find("none.cpm"), std::string::npos) << r.err;
	r = runProcess(gPlay, { "--input", dir_ + "/missing", "--model", dir_ + "/none.cpm" }, dir_);
	EXPECT_EQ(r.exitCode, 1);
	EXPECT_NE(r.err.find("missing"), std::string::npos) << r.err;
}

// SIGTERM mid-stream: the loop finishes its frame, stops the source and exits 0.
TEST_F(LiveExample, PlayStopsCleanlyOnSigterm)
{
	if (model_.empty())
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	const std::string out = dir_ + "/out.jsonl", err = dir_ + "/err.txt";
	const std::vector<std::string> args = { gPlay, "--input", dir_ + "/frames", "--model", model_,
						"--loop", "--fps", "20" };
	std::vector<char *> argv;
	for (const std::string &a : args)
		argv.push_back(const_cast<char *>(a.c_str()));
	argv.push_back(nullptr);
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
	pid_t pid = -1;
	ASSERT_EQ(posix_spawn(&pid, gPlay.c_str(), &actions, nullptr, argv.data(), environ), 0);
	posix_spawn_file_actions_destroy(&actions);
	std::this_thread::sleep_for(std::chrono::milliseconds(1500));
	kill(pid, SIGTERM);
	const auto t0 = std::chrono::steady_clock::now();
	int status = 0;
	waitpid(pid, &status, 0);
	const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
	// 128 + SIGTERM: stopped by the signal, after finishing the frame (docs/ports.md).
	EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << calped::test::readTextFile(err);
	EXPECT_LT(seconds, 3.0);
	const auto lines = splitLines(calped::test::readTextFile(out));
	EXPECT_GE(lines.size(), 5u);
	expectJsonLines(lines);
}

TEST_F(LiveExample, AravisWithoutSuchCameraFails)
{
	if (gAravis.empty())
		GTEST_SKIP() << "calped-aravis not built (no Aravis): skipping";
	const ProcessResult r =
		runProcess(gAravis, { "--camera", "calped-no-such-camera", "--model", dir_ + "/x" }, dir_);
	EXPECT_EQ(r.exitCode, 1);
	EXPECT_NE(r.err.find("CameraNotFound"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("calped-no-such-camera"), std::string::npos) << r.err;
}

TEST_F(LiveExample, AravisStreamsFramesFromTheSimulator)
{
	if (gAravis.empty())
		GTEST_SKIP() << "calped-aravis not built (no Aravis): skipping";
	if (calped::test::fakeGvCameraPath().empty())
		GTEST_SKIP() << "aravis-tools is not installed (no arv-fake-gv-camera-0.8 on PATH): skipping";
	if (model_.empty())
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	calped::test::FakeGvCamera fake;
	std::string why;
	ASSERT_TRUE(fake.start("127.0.0.1", 0, why)) << why;
	const ProcessResult r = runProcess(gAravis, { "--camera", "127.0.0.1", "--pixel-format", "RGB8",
						      "--model", model_, "--frames", "10" }, dir_);
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0) << r.err;
	const auto lines = splitLines(r.out);
	EXPECT_EQ(lines.size(), 10u);
	expectJsonLines(lines);
	EXPECT_NE(r.err.find("processed 10,"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("incomplete 0,"), std::string::npos) << r.err;
}

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		if (a.rfind("--play=", 0) == 0)
			gPlay = a.substr(7);
		else if (a.rfind("--aravis=", 0) == 0)
			gAravis = a.substr(9);
	}
	if (gPlay.empty()) {
		std::fprintf(stderr, "usage: live_example_tests --play=PATH [--aravis=PATH]\n");
		return 2;
	}
	return RUN_ALL_TESTS();
}
