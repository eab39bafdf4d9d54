// SPDX-License-Identifier: BSD-2-Clause
// calped-libcamera as a black box where libcamera finds no camera: one error line, exit
// status 1, nothing on stdout; usage errors exit 2. The camera case skips where one exists.
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <unistd.h>

#include "libcamera_source.h"
#include "process.h"

namespace calped {
namespace ports {
namespace {

using test::ProcessResult;
using test::runProcess;
using test::splitLines;

std::string program()
{
	const char *build = std::getenv("CALPED_BUILD_DIR");
	return std::string(build ? build : ".") + "/examples/libcamera/calped-libcamera";
}

std::string scratchDir()
{
	char dir[] = "/tmp/calped-libcamera-cli-XXXXXX";
	return mkdtemp(dir) ? dir : "/tmp";
}

bool cameraExists()
{
	std::unique_ptr<FrameSource> source;
	return openLibcameraSource(LibcameraOptions(), source).code() != ErrorCode::CameraNotFound;
}

void expectOneLineError(const ProcessResult &r, int code, const std::string &start)
{
	ASSERT_TRUE(r.exited) << "killed by signal " << r.signal << "; stderr:\n" << r.err;
	EXPECT_EQ(r.exitCode, code) << "stderr:\n" << r.err;
	EXPECT_EQ(r.out, "");
	std::vector<std::string> lines = splitLines(r.err);
	ASSERT_EQ(lines.size(), 1u) << "stderr:\n" << r.err;
	EXPECT_EQ(lines[0].rfind(start, 0), 0u) << lines[0];
}

TEST(LibcameraCli, NoCameraIsOneLineAndExitStatusOne)
{
	if (cameraExists())
		GTEST_SKIP() << "libcamera finds a camera here";
	// The camera is opened before the model is read, so no model is needed.
	for (const char *camera : { "0", "/base/soc/i2c0mux/i2c@1/imx219@10" }) {
		ProcessResult r = runProcess(program(),
					     { "--camera", camera, "--model", "unused.cpm", "--frames", "3" },
					     scratchDir());
		expectOneLineError(r, 1, "calped-libcamera: CameraNotFound: libcamera found no camera");
		EXPECT_NE(r.err.find(camera), std::string::npos) << r.err;
	}
	ProcessResult r = runProcess(program(), { "--model", "unused.cpm" }, scratchDir());
	expectOneLineError(r, 1, "calped-libcamera: CameraNotFound: libcamera found no camera");
}

TEST(LibcameraCli, UsageErrorsExitTwo)
{
	const std::vector<std::vector<std::string>> bad = {
		{ "--camera", "0" }, // no --model
		{ "--model", "m.cpm", "--format", "mjpeg" },
		{ "--model", "m.cpm", "--size", "640" },
		{ "--model", "m.cpm", "--size", "0x480" },
		{ "--model", "m.cpm", "--fps", "0" },
		{ "--model", "m.cpm", "--buffers", "1" },
		{ "--model", "m.cpm", "--lost-after", "-1" },
		{ "--model", "m.cpm", "--frobnicate", "1" },
	};
	for (const auto &args : bad) {
		SCOPED_TRACE(args[args.size() - 2] + " " + args.back());
		expectOneLineError(runProcess(program(), args, scratchDir()), 2, "calped-libcamera: ");
	}
}

TEST(LibcameraCli, HelpListsTheCameraOptions)
{
	ProcessResult r = runProcess(program(), { "--help" }, scratchDir());
	ASSERT_TRUE(r.exited);
	EXPECT_EQ(r.exitCode, 0);
	for (const char *option : { "--camera", "--format", "--size", "--fps", "--lost-after", "--frames",
				    "--model" })
		EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

} // namespace
} // namespace ports
} // namespace calped
