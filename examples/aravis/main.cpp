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

namespace {

const char *kProgram = "calped-aravis";

void printUsage()
{
	std::fputs("usage: calped-aravis --camera ID --model BLOB [options]\n"
		   "\n"
		   "Runs the detector live on a GigE Vision camera through Aravis.\n"
		   "\n"
		   "camera options:\n"
		   "  --camera ID         Aravis device id or IP address (default: the first camera)\n"
		   "  --pixel-format F    GenICam PixelFormat: Mono8, RGB8, BGR8, YUV422_YUYV_Packed,\n"
		   "                      BayerRG8, ... (default: the camera's)\n"
		   "  --width W, --height H   region size (default: the camera's)\n"
		   "  --fps F             acquisition frame rate (default: the camera's)\n"
		   "  --buffers N         buffer pool size, 2..64 (default 4)\n"
		   "  --packet-size B     GigE packet size in bytes (default: the camera's)\n"
		   "  --socket-buffer B   UDP receive buffer bytes (default: 4 payloads, 1..64 MiB)\n"
		   "  --packet-socket     use Aravis's packet socket (needs CAP_NET_RAW; default off)\n"
		   "  --no-packet-resend  never ask the camera to resend lost packets\n"
		   "  --packet-timeout MS, --frame-retention MS   Aravis stream timeouts\n"
		   "  --lost-after MS     no frame for MS: check the camera answers (default 2000)\n"
		   "  --reconnect         reopen the camera after a loss instead of exiting\n"
		   "\n",
		   stdout);
	std::fputs(calped::live::liveUsageText(), stdout);
}

// Adds Aravis's transport counters to the stats line.
class AravisReporter : public calped::live::StatsReporter
{
public:
	explicit AravisReporter(const calped::ports::AravisSource &source) : source_(source) {}
	void appendStats(char *line, size_t size) const override
	{
		const calped::ports::AravisStats t = source_.transportStats();
		std::snprintf(line, size, ", never seen %" PRIu64 ", resent packets %" PRIu64
				  ", missing packets %" PRIu64,
			      t.unseenFrames, t.resentPackets, t.missingPackets);
	}

private:
	const calped::ports::AravisSource &source_;
};

bool parseCount(const calped::live::Arg &arg, long lo, long hi, int &out, std::string &error)
{
	long v = 0;
	if (!calped::live::parseWhole(arg.value, v) || v < lo || v > hi) {
		error = arg.name + " must be a whole number from " + std::to_string(lo) + " to " +
			std::to_string(hi) + ", got '" + arg.value + "'";
		return false;
	}
	out = static_cast<int>(v);
	return true;
}

int run(int argc, char **argv)
{
	using namespace calped;
	std::vector<live::Arg> args;
	std::string error;
	if (!live::splitArgs(argc, argv, { "--packet-socket", "--no-packet-resend", "--reconnect" },
			     { "--camera", "--pixel-format", "--width", "--height", "--fps", "--buffers",
			       "--packet-size", "--socket-buffer", "--packet-timeout", "--frame-retention",
			       "--lost-after" },
			     args, error))
		return cliFail(kProgram, kExitUsage, error);
	live::LiveOptions options;
	ports::AravisOptions cam;
	for (const live::Arg &arg : args) {
		const live::ParseResult r = live::parseLiveOption(arg, options, error);
		if (r == live::ParseResult::Error)
			return cliFail(kProgram, kExitUsage, error);
		if (r == live::ParseResult::Ok)
			continue;
		const std::string &n = arg.name;
		bool ok = true;
		if (n == "--camera")
			cam.camera = arg.value;
		else if (n == "--pixel-format")
			cam.pixelFormat = arg.value;
		else if (n == "--width")
			ok = parseCount(arg, 1, 65535, cam.width, error);
		else if (n == "--height")
			ok = parseCount(arg, 1, 65535, cam.height, error);
		else if (n == "--buffers")
			ok = parseCount(arg, 2, 64, cam.buffers, error);
		else if (n == "--packet-size")
			ok = parseCount(arg, 576, 65535, cam.packetSize, error);
		else if (n == "--socket-buffer")
			ok = parseCount(arg, 65536, 1 << 30, cam.socketBufferBytes, error);
		else if (n == "--packet-timeout")
			ok = parseCount(arg, 1, 10000, cam.packetTimeoutMs, error);
		else if (n == "--frame-retention")
			ok = parseCount(arg, 1, 60000, cam.frameRetentionMs, error);
		else if (n == "--lost-after")
			ok = parseCount(arg, 100, 600000, cam.lostAfterMs, error);
		else if (n == "--packet-socket")
			cam.packetSocket = true;
		else if (n == "--no-packet-resend")
			cam.packetResend = false;
		else if (n == "--reconnect")
			cam.reconnect = true;
		else if (n == "--fps") {
			ok = live::parseNumber(arg.value, cam.frameRate) && cam.frameRate > 0 &&
			     cam.frameRate <= 10000;
			if (!ok)
				error = "--fps must be a number > 0, got '" + arg.value + "'";
		} else
			return cliFail(kProgram, kExitUsage, "unknown option '" + n + "' (try --help)");
		if (!ok)
			return cliFail(kProgram, kExitUsage, error);
	}
	if (options.help) {
		printUsage();
		return 0;
	}
	if (!live::checkLiveOptions(options, error))
		return cliFail(kProgram, kExitUsage, error);

	std::unique_ptr<ports::AravisSource> source;
	const Status st = ports::AravisSource::open(cam, source);
	if (!st.ok())
		return cliFail(kProgram, kExitRuntime, st.message());
	AravisReporter reporter(*source);
	return live::runLive(*source, options, kProgram, &reporter);
}

} // namespace

int main(int argc, char **argv)
{
	const int code = calped::runGuarded(kProgram, [&] { return run(argc, argv); });
	arv_shutdown(); // frees Aravis's global state (interfaces, device lists)
	return code;
}
