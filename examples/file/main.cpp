// SPDX-License-Identifier: BSD-2-Clause
// calped-play: the file source (an image folder or a video) through the live loop, as if
// it were a camera. See docs/ports.md.
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "cli_error.h"
#include "file_source.h"
#include "live_loop.h"
#include "live_options.h"

namespace {

const char *kProgram = "calped-play";

void printUsage()
{
	std::fputs("usage: calped-play --input PATH --model BLOB [options]\n"
		   "\n"
		   "Plays an image folder (PNG, JPEG, PPM, PGM in name order), one image or a video\n"
		   "file (decoded by ffmpeg) through the detector like a live camera.\n"
		   "\n"
		   "source options:\n"
		   "  --input PATH        image file, image folder or video file\n"
		   "  --fps F             pace frames at F per second (default: as fast as processed)\n"
		   "  --loop              start again after the last frame (stop with --frames or SIGINT)\n"
		   "\n",
		   stdout);
	std::fputs(calped::live::liveUsageText(), stdout);
}

int run(int argc, char **argv)
{
	using namespace calped;
	std::vector<live::Arg> args;
	std::string error;
	if (!live::splitArgs(argc, argv, { "--loop" }, { "--input", "--fps" }, args, error))
		return cliFail(kProgram, kExitUsage, error);
	live::LiveOptions options;
	ports::FileSourceOptions source;
	for (const live::Arg &arg : args) {
		const live::ParseResult r = live::parseLiveOption(arg, options, error);
		if (r == live::ParseResult::Error)
			return cliFail(kProgram, kExitUsage, error);
		if (r == live::ParseResult::Ok)
			continue;
		if (arg.name == "--input") {
			source.path = arg.value;
		} else if (arg.name == "--loop") {
			source.loop = true;
		} else if (arg.name == "--fps") {
			if (!live::parseNumber(arg.value, source.fps) || !(source.fps > 0) || source.fps > 1000)
				return cliFail(kProgram, kExitUsage,
					       "--fps must be a number > 0 and <= 1000, got '" + arg.value + "'");
		} else {
			return cliFail(kProgram, kExitUsage, "unknown option '" + arg.name + "' (try --help)");
		}
	}
	if (options.help) {
		printUsage();
		return 0;
	}
	if (source.path.empty())
		return cliFail(kProgram, kExitUsage, "missing --input PATH (try --help)");
	if (!live::checkLiveOptions(options, error))
		return cliFail(kProgram, kExitUsage, error);

	std::unique_ptr<ports::FileSource> src;
	const Status st = ports::FileSource::open(source, src);
	if (!st.ok())
		return cliFail(kProgram, kExitRuntime, st.message());
	return live::runLive(*src, options, kProgram);
}

} // namespace

int main(int argc, char **argv)
{
	return calped::runGuarded(kProgram, [&] { return run(argc, argv); });
}
