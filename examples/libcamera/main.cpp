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

namespace {

const char *kProgram = "calped-libcamera";

void printUsage()
{
	std::fputs("usage: calped-libcamera --camera ID|INDEX --model BLOB [options]\n"
		   "\n"
		   "Runs the detector live on a libcamera camera (docs/libcamera.md).\n"
		   "\n"
		   "camera options:\n"
		   "  --camera ID|INDEX   camera id as `cam --list` prints it, or its index there\n"
		   "                      (default: the first camera)\n"
		   "  --format F          nv12, yuv420, yuyv, rgb888 (B,G,R bytes) or bgr888\n"
		   "                      (R,G,B bytes), as libcamera names them (default: the\n"
		   "                      first of these the camera offers)\n"
		   "  --size WxH          frame size (default: the camera's); the camera may adjust it\n"
		   "  --fps F             frame rate through FrameDurationLimits (default: the camera's)\n"
		   "  --buffers N         buffer pool size, 2..16 (default 4)\n"
		   "  --lost-after MS     no complete frame for MS: camera lost, exit 1\n"
		   "                      (default 10000; 0: wait forever)\n"
		   "\n",
		   stdout);
	std::fputs(calped::live::liveUsageText(), stdout);
	std::fputs("A missing camera is a runtime error: exit status 1, message starting with\n"
		   "\"calped-libcamera: CameraNotFound:\".\n",
		   stdout);
}

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

// "WxH" with 1 <= W, H <= 16384.
bool parseSize(const std::string &text, int &width, int &height)
{
	const size_t x = text.find('x');
	long w = 0, h = 0;
	if (x == std::string::npos || !calped::live::parseWhole(text.substr(0, x), w) ||
	    !calped::live::parseWhole(text.substr(x + 1), h))
		return false;
	if (w < 1 || h < 1 || w > 16384 || h > 16384)
		return false;
	width = static_cast<int>(w);
	height = static_cast<int>(h);
	return true;
}

int run(int argc, char **argv)
{
	using namespace calped;
	std::vector<live::Arg> args;
	std::string error;
	if (!live::splitArgs(argc, argv, {}, args, error))
		return cliFail(kProgram, kExitUsage, error);
	live::LiveOptions options;
	ports::LibcameraOptions camera;
	for (const live::Arg &arg : args) {
		const live::ParseResult r = live::parseLiveOption(arg, options, error);
		if (r == live::ParseResult::Error)
			return cliFail(kProgram, kExitUsage, error);
		if (r == live::ParseResult::Ok)
			continue;
		if (arg.name == "--camera") {
			camera.camera = arg.value;
		} else if (arg.name == "--format") {
			if (!parseFormat(arg.value, camera.format))
				return cliFail(kProgram, kExitUsage,
					       "--format must be nv12, yuv420, yuyv, rgb888 or bgr888, got '" +
						       arg.value + "'");
		} else if (arg.name == "--size") {
			if (!parseSize(arg.value, camera.width, camera.height))
				return cliFail(kProgram, kExitUsage,
					       "--size must be WxH with W and H from 1 to 16384, got '" +
						       arg.value + "'");
		} else if (arg.name == "--fps") {
			if (!live::parseNumber(arg.value, camera.fps) || !(camera.fps > 0) ||
			    camera.fps > 1000)
				return cliFail(kProgram, kExitUsage,
					       "--fps must be a number > 0 and <= 1000, got '" + arg.value + "'");
		} else if (arg.name == "--buffers") {
			long n = 0;
			if (!live::parseWhole(arg.value, n) || n < 2 || n > 16)
				return cliFail(kProgram, kExitUsage,
					       "--buffers must be a whole number from 2 to 16, got '" +
						       arg.value + "'");
			camera.buffers = static_cast<int>(n);
		} else if (arg.name == "--lost-after") {
			long ms = 0;
			if (!live::parseWhole(arg.value, ms) || ms < 0 || ms > 3600000)
				return cliFail(kProgram, kExitUsage,
					       "--lost-after must be a whole number of ms from 0 to 3600000, got '" +
						       arg.value + "'");
			camera.lostAfterMs = static_cast<int>(ms);
		} else {
			return cliFail(kProgram, kExitUsage, "unknown option '" + arg.name + "' (try --help)");
		}
	}
	if (options.help) {
		printUsage();
		return 0;
	}
	if (!live::checkLiveOptions(options, error))
		return cliFail(kProgram, kExitUsage, error);

	std::unique_ptr<ports::FrameSource> source;
	const Status st = ports::openLibcameraSource(camera, source);
	if (!st.ok())
		return cliFail(kProgram, kExitRuntime, st.message());
	return live::runLive(*source, options, kProgram);
}

} // namespace

int main(int argc, char **argv)
{
	return calped::runGuarded(kProgram, [&] { return run(argc, argv); });
}
