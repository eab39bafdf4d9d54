// SPDX-License-Identifier: BSD-2-Clause
// calped-play: the file source (an image folder or a video) through the live loop, as if
// it were a camera. See docs/ports.md.
#include <memory>
#include <string>
#include <vector>

#include "cli_error.h"
#include "file_source.h"
#include "live_loop.h"
#include "live_options.h"
#include "program.h"

namespace {

using namespace calped;

const apps::ProgramInfo kProgram = {
	"calped-play",
	"usage: calped-play --input PATH --model BLOB [options]\n"
	"\n"
	"Plays an image folder (PNG, JPEG, PPM, PGM in name order), one image or a video\n"
	"file (decoded by ffmpeg) through the detector like a live camera.\n"
	"\n"
	"source options:\n",
	live::liveEpilogue(),
};

int run(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> own = {
		{ "input", "PATH", "image file, image folder or video file" },
		{ "fps", "F", "pace frames at F per second (default: as fast as processed)" },
		{ "loop", nullptr, "start again after the last frame (stop with --frames or SIGINT)" },
	};
	live::LiveOptions options;
	apps::ParsedArgs args;
	const int rc = live::parseLiveCommandLine(kProgram, own, argc, argv, options, args);
	if (rc >= 0)
		return rc;
	ports::FileSourceOptions source;
	std::string error;
	for (const apps::ParsedOption &o : args.options) {
		if (o.name == "input")
			apps::nonEmpty(o, "a file or folder name", source.path, error);
		else if (o.name == "fps")
			apps::numberIn(o, 0, true, 1000, source.fps, error);
		else if (o.name == "loop")
			source.loop = true;
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (source.path.empty())
		return apps::usageError(kProgram, "missing --input PATH (try --help)");
	if (!live::checkLiveOptions(options, error))
		return apps::usageError(kProgram, error);

	std::unique_ptr<ports::FileSource> src;
	const Status st = ports::FileSource::open(source, src);
	if (!st.ok())
		return apps::cliFail(kProgram.name, apps::kExitRuntime, st.message());
	return live::runLive(*src, options, kProgram.name);
}

} // namespace

int main(int argc, char **argv)
{
	return calped::apps::runGuarded(kProgram.name, [&] { return run(argc, argv); });
}
