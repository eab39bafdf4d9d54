// SPDX-License-Identifier: BSD-2-Clause
#include "live_options.h"

#include <limits>

namespace calped {
namespace live {

std::vector<apps::OptionSpec> liveOptionTable()
{
	const std::vector<apps::OptionSpec> t = apps::joinOptions(
		{ { nullptr, nullptr, "detector and output options:" } },
		apps::detectorOptionTable(apps::DetectorFlags::All));
	return apps::joinOptions(apps::joinOptions(t, {
		{ "overlay", "DIR", "save DIR/NNNNNN.png (frame id) with the detections drawn" },
		{ "overlay-every", "K", "overlay every K-th processed frame (default 1)" },
		{ "frames", "N", "stop after N processed frames, exit status 0" },
		{ "timeout", "MS", "wait per frame before counting a timeout (default 2000)" },
		{ "frame-timeout", "S", "fail after S seconds without a complete frame (default 30,\n"
					"0 waits for ever)" },
		{ "stats-every", "S", "seconds between stats lines on stderr (default 5)" },
		{ "quiet", nullptr, "no stats lines" },
	}), apps::mqttOptionTable());
}

bool takeLiveOption(const apps::ParsedOption &o, LiveOptions &out, std::string &error)
{
	if (apps::takeDetectorOption(o, out.detector, error) || apps::takeMqttOption(o, out.mqtt, error))
		return true;
	const std::string &n = o.name;
	if (n == "overlay")
		apps::nonEmpty(o, "a folder name", out.overlayDir, error);
	else if (n == "overlay-every")
		apps::wholeIn(o, 1, 1000000000L, out.overlayEvery, error);
	else if (n == "frames")
		apps::wholeIn(o, 1, std::numeric_limits<long>::max(), out.frames, error);
	else if (n == "timeout")
		apps::wholeIn(o, 1, 600000L, out.timeoutMs, error);
	else if (n == "frame-timeout")
		apps::numberIn(o, 0, true, 86400, out.frameTimeoutS, error);
	else if (n == "stats-every")
		apps::numberIn(o, 0, true, 86400, out.statsEvery, error);
	else if (n == "quiet")
		out.quiet = true;
	else
		return false;
	return true;
}

bool checkLiveOptions(LiveOptions &options, std::string &error)
{
	return apps::checkDetectorOptions(options.detector, true, apps::DetectorFlags::All, error) &&
	       apps::checkMqttOptions(options.mqtt, error);
}

int parseLiveCommandLine(const apps::ProgramInfo &program, const std::vector<apps::OptionSpec> &own,
			 int argc, const char *const *argv, LiveOptions &options, apps::ParsedArgs &rest)
{
	return apps::parseCommandLine(program, apps::joinOptions(own, liveOptionTable()), false, argc,
				      argv, rest, [&](const apps::ParsedOption &o, std::string &error) {
					      return takeLiveOption(o, options, error);
				      });
}

const char *liveEpilogue()
{
	return "\n"
	       "Standard output: one JSON object per processed frame (docs/ports.md).\n"
	       "SIGINT and SIGTERM stop after the current frame: complete JSON lines, exit status\n"
	       "128 + the signal (130, 143).\n"
	       "exit status: 0 success, 1 runtime error (camera lost, no complete frame within\n"
	       "--frame-timeout, bad model, ...), 2 usage error, 130/143 stopped by SIGINT/SIGTERM\n";
}

} // namespace live
} // namespace calped
