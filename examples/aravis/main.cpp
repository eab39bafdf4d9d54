// SPDX-License-Identifier: BSD-2-Clause
// calped-aravis: a GigE Vision camera (through Aravis) through the live loop.
// See docs/ports.md.
#include <cinttypes>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <arv.h>

#include "aravis_source.h"
#include "cli_error.h"
#include "live_loop.h"
#include "live_options.h"
#include "program.h"

namespace {

using namespace calped;

const apps::ProgramInfo kProgram = {
	"calped-aravis",
	"usage: calped-aravis --camera ID --model BLOB [options]\n"
	"\n"
	"Runs the detector live on a GigE Vision camera through Aravis.\n"
	"\n"
	"camera options:\n",
	live::liveEpilogue(),
};

// Adds Aravis's transport counters to the stats line.
class AravisReporter : public calped::live::StatsReporter
{
public:
	explicit AravisReporter(const calped::ports::AravisSource &source) : source_(source) {}
	void appendStats(char *line, size_t size) const override
	{
		const calped::ports::AravisStats t = source_.transportStats();
		std::snprintf(line, size, ", never seen %" PRIu64 " (%" PRIu64 " estimated lost while reconnecting)"
				  ", resent packets %" PRIu64 ", missing packets %" PRIu64,
			      t.unseenFrames, t.lostAcrossReconnects, t.resentPackets, t.missingPackets);
	}

private:
	const calped::ports::AravisSource &source_;
};

int run(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> own = {
		{ "camera", "ID", "Aravis device id or IP address (default: the first camera)" },
		{ "pixel-format", "F", "GenICam PixelFormat: Mono8, RGB8, BGR8, YUV422_YUYV_Packed,\n"
				       "BayerRG8, ... (default: the camera's)" },
		{ "width", "W", "region width (default: the camera's)" },
		{ "height", "H", "region height (default: the camera's)" },
		{ "fps", "F", "acquisition frame rate (default: the camera's)" },
		{ "buffers", "N", "buffer pool size, 2..64 (default 4)" },
		{ "packet-size", "B", "GigE packet size in bytes (default: the camera's)" },
		{ "socket-buffer", "B", "UDP receive buffer bytes (default: 4 payloads, 1..64 MiB)" },
		{ "packet-socket", nullptr, "use Aravis's packet socket (needs CAP_NET_RAW; default off)" },
		{ "no-packet-resend", nullptr, "never ask the camera to resend lost packets" },
		{ "packet-timeout", "MS", "Aravis stream packet timeout" },
		{ "frame-retention", "MS", "Aravis stream frame retention" },
		{ "lost-after", "MS", "no frame for MS: check the camera answers (default 2000)" },
		{ "reconnect", nullptr, "reopen the camera after a loss instead of exiting" },
	};
	live::LiveOptions options;
	apps::ParsedArgs args;
	const int rc = live::parseLiveCommandLine(kProgram, own, argc, argv, options, args);
	if (rc >= 0)
		return rc;
	ports::AravisOptions cam;
	std::string error;
	for (const apps::ParsedOption &o : args.options) {
		const std::string &n = o.name;
		struct Count {
			const char *name;
			long lo, hi;
			int *out;
		};
		const Count counts[] = {
			{ "width", 1, 65535, &cam.width },
			{ "height", 1, 65535, &cam.height },
			{ "buffers", 2, 64, &cam.buffers },
			{ "packet-size", 576, 65535, &cam.packetSize },
			{ "socket-buffer", 65536, 1 << 30, &cam.socketBufferBytes },
			{ "packet-timeout", 1, 10000, &cam.packetTimeoutMs },
			{ "frame-retention", 1, 60000, &cam.frameRetentionMs },
			{ "lost-after", 100, 600000, &cam.lostAfterMs },
		};
		bool counted = false;
		for (const Count &c : counts) {
			long v = 0;
			if (n != c.name)
				continue;
			counted = true;
			if (apps::wholeIn(o, c.lo, c.hi, v, error))
				*c.out = static_cast<int>(v);
		}
		if (counted) {
			// a number, parsed above
		} else if (n == "camera") {
			cam.camera = o.value;
		} else if (n == "pixel-format") {
			cam.pixelFormat = o.value;
		} else if (n == "packet-socket") {
			cam.packetSocket = true;
		} else if (n == "no-packet-resend") {
			cam.packetResend = false;
		} else if (n == "reconnect") {
			cam.reconnect = true;
		} else if (n == "fps") {
			apps::numberIn(o, 0, true, 10000, cam.frameRate, error);
		}
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (!live::checkLiveOptions(options, error))
		return apps::usageError(kProgram, error);

	std::unique_ptr<ports::AravisSource> source;
	const Status st = ports::AravisSource::open(cam, source);
	if (!st.ok())
		return apps::cliFail(kProgram.name, apps::kExitRuntime, st.message());
	AravisReporter reporter(*source);
	return live::runLive(*source, options, kProgram.name, &reporter);
}

} // namespace

int main(int argc, char **argv)
{
	const int code = calped::apps::runGuarded(kProgram.name, [&] { return run(argc, argv); });
	arv_shutdown(); // frees Aravis's global state (interfaces, device lists)
	return code;
}
