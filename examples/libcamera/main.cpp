// SPDX-License-Identifier: BSD-2-Clause
// calped-libcamera: a libcamera camera (Raspberry Pi camera modules, UVC webcams, ...)
// through the live loop. See docs/libcamera.md.
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "cli_error.h"
#include "libcamera_source.h"
#include "live_loop.h"
#include "live_options.h"
#include "program.h"

namespace {

using namespace calped;

const apps::ProgramInfo kProgram = {
	"calped-libcamera",
	"usage: calped-libcamera --camera ID|INDEX --model BLOB [options]\n"
	"\n"
	"Runs the detector live on a libcamera camera (docs/libcamera.md).\n"
	"\n"
	"camera options:\n",
	"\n"
	"Standard output: one JSON object per processed frame (docs/ports.md).\n"
	"SIGINT and SIGTERM stop cleanly (exit status 0).\n"
	"A missing camera is a runtime error: exit status 1, message starting with\n"
	"\"calped-libcamera: CameraNotFound:\".\n"
	"exit status: 0 success, 1 runtime error (camera lost, bad model, ...), 2 usage error\n",
};

bool parseFormat(const std::string &text, std::optional<calped::PixelFormat> &out)
{
	using calped::PixelFormat;
	struct Name {
		const char *name;
		PixelFormat format;
	};
	// libcamera's names: DRM fourccs, so "RGB888" is B,G,R in memory (calped's BGR8).
	const Name names[] = { { "nv12", PixelFormat::NV12 },   { "yuv420", PixelFormat::YUV420 },
			       { "yuyv", PixelFormat::YUYV },   { "rgb888", PixelFormat::BGR8 },
			       { "bgr888", PixelFormat::RGB8 } };
	for (const Name &n : names) {
		if (text == n.name) {
			out = n.format;
			return true;
		}
	}
	return false;
}

int run(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> own = {
		{ "camera", "ID|INDEX", "camera id as `cam --list` prints it, or its index there\n"
					"(default: the first camera)" },
		{ "format", "F", "nv12, yuv420, yuyv, rgb888 (B,G,R bytes) or bgr888 (R,G,B\n"
				 "bytes), as libcamera names them (default: the first of these\n"
				 "the camera offers)" },
		{ "size", "WxH", "frame size (default: the camera's); the camera may adjust it" },
		{ "fps", "F", "frame rate through FrameDurationLimits (default: the camera's)" },
		{ "buffers", "N", "buffer pool size, 2..16 (default 4)" },
		{ "lost-after", "MS", "no complete frame for MS: camera lost, exit 1\n"
				      "(default 10000; 0: wait forever)" },
	};
	live::LiveOptions options;
	apps::ParsedArgs args;
	const int rc = live::parseLiveCommandLine(kProgram, own, argc, argv, options, args);
	if (rc >= 0)
		return rc;
	ports::LibcameraOptions camera;
	std::string error;
	for (const apps::ParsedOption &o : args.options) {
		long n = 0;
		if (o.name == "camera") {
			camera.camera = o.value;
		} else if (o.name == "format") {
			if (!parseFormat(o.value, camera.format))
				error = apps::badValue(o, "nv12, yuv420, yuyv, rgb888 or bgr888");
		} else if (o.name == "size") {
			if (!apps::parseFrameSize(o.value, camera.width, camera.height))
				error = apps::badValue(o, "WxH with W and H from 1 to 16384");
		} else if (o.name == "fps") {
			apps::numberIn(o, 0, true, 1000, camera.fps, error);
		} else if (o.name == "buffers") {
			if (apps::wholeIn(o, 2, 16, n, error))
				camera.buffers = static_cast<int>(n);
		} else if (o.name == "lost-after") {
			if (apps::wholeIn(o, 0, 3600000, n, error))
				camera.lostAfterMs = static_cast<int>(n);
		}
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (!live::checkLiveOptions(options, error))
		return apps::usageError(kProgram, error);

	std::unique_ptr<ports::FrameSource> source;
	const Status st = ports::openLibcameraSource(camera, source);
	if (!st.ok())
		return apps::cliFail(kProgram.name, apps::kExitRuntime, st.message());
	return live::runLive(*source, options, kProgram.name);
}

} // namespace

int main(int argc, char **argv)
{
	return calped::apps::runGuarded(kProgram.name, [&] { return run(argc, argv); });
}
