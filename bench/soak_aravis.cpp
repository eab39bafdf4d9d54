// SPDX-License-Identifier: BSD-2-Clause
// soak_aravis: the Aravis port against Debian's GigE Vision simulator for a long run, with
// packet loss and a camera restart in the middle (docs/ports.md, "Soak"). Reports frames
// processed, dropped and incomplete frames by reason, RSS at start, middle and end,
// operator new calls per frame, and how long the stream took to come back.
//
//   soak_aravis [--duration S] [--lost-ratio PER_THOUSAND] [--restart-at S]
//               [--model BLOB] [--pixel-format F] [--address A]
#include <arv.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include <calped/calped.h>

#include "detector_options.h"

#include "aravis_source.h"
#include "fake_gv_camera.h"

namespace {

std::atomic<long> gAllocations{ 0 };

void *countedAlloc(size_t size)
{
	gAllocations++;
	void *p = std::malloc(size ? size : 1);
	if (!p)
		throw std::bad_alloc();
	return p;
}

long rssKiB()
{
	FILE *f = std::fopen("/proc/self/status", "r");
	if (!f)
		return -1;
	char line[256];
	long kib = -1;
	while (std::fgets(line, sizeof(line), f))
		if (std::sscanf(line, "VmRSS: %ld kB", &kib) == 1)
			break;
	std::fclose(f);
	return kib;
}

struct Options {
	double duration = 600;
	int lostRatio = 2; // per thousand stream packets
	double restartAt = -1; // default: half the duration
	double downSeconds = 2; // how long the camera stays away
	std::string model;
	std::string pixelFormat = "RGB8";
	std::string address = "127.0.0.1";
};

bool parse(int argc, char **argv, Options &o)
{
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		if (i + 1 >= argc)
			return false;
		const char *v = argv[++i];
		if (a == "--duration")
			o.duration = std::atof(v);
		else if (a == "--lost-ratio")
			o.lostRatio = std::atoi(v);
		else if (a == "--restart-at")
			o.restartAt = std::atof(v);
		else if (a == "--down")
			o.downSeconds = std::atof(v);
		else if (a == "--model")
			o.model = v;
		else if (a == "--pixel-format")
			o.pixelFormat = v;
		else if (a == "--address")
			o.address = v;
		else
			return false;
	}
	if (o.restartAt < 0)
		o.restartAt = o.duration / 2;
	return o.duration > 0 && o.lostRatio >= 0;
}

std::unique_ptr<calped::Detector> makeDetector(const std::string &path, int w, int h)
{
	FILE *f = std::fopen(path.c_str(), "rb");
	if (!f)
		return nullptr;
	std::vector<uint8_t> blob;
	uint8_t buf[65536];
	size_t n;
	while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0)
		blob.insert(blob.end(), buf, buf + n);
	std::fclose(f);
	calped::Model model;
	if (!calped::loadModel(blob.data(), blob.size(), model).ok())
		return nullptr;
	// The programs' DetectorConfig (tools/common) at its defaults: generic, resize 1.
	const calped::DetectorConfig config =
		calped::apps::makeDetectorConfig(calped::apps::DetectorOptions(), w, h, nullptr);
	std::unique_ptr<calped::Detector> det;
	if (!calped::Detector::create(model, config, det).ok())
		return nullptr;
	return det;
}

} // namespace

void *operator new(size_t size) { return countedAlloc(size); }
void *operator new[](size_t size) { return countedAlloc(size); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, size_t) noexcept { std::free(p); }
void operator delete[](void *p, size_t) noexcept { std::free(p); }

int main(int argc, char **argv)
{
	using namespace calped;
	using namespace calped::ports;
	using Clock = std::chrono::steady_clock;
	Options o;
	if (!parse(argc, argv, o)) {
		std::fprintf(stderr, "usage: soak_aravis [--duration S] [--lost-ratio N] [--restart-at S] "
				     "[--down S] [--model BLOB] [--pixel-format F] [--address A]\n");
		return 2;
	}
	test::FakeGvCamera fake;
	std::string why;
	if (!fake.start(o.address, o.lostRatio, why)) {
		std::fprintf(stderr, "soak_aravis: %s\n", why.c_str());
		return 1;
	}
	AravisOptions options;
	options.camera = o.address;
	options.pixelFormat = o.pixelFormat;
	options.reconnect = true;
	options.lostAfterMs = 1000;
	options.reconnectEveryMs = 250;
	std::unique_ptr<AravisSource> src;
	Status st = AravisSource::open(options, src);
	if (!st.ok() || !(st = src->start()).ok()) {
		std::fprintf(stderr, "soak_aravis: %s\n", st.message());
		return 1;
	}
	int w = 0, h = 0;
	src->frameSize(w, h);
	std::unique_ptr<Detector> det;
	if (!o.model.empty() && !(det = makeDetector(o.model, w, h))) {
		std::fprintf(stderr, "soak_aravis: cannot load %s\n", o.model.c_str());
		return 1;
	}
	std::printf("soak_aravis: %s, %.0f s, %d/1000 packets lost, camera restart at %.0f s (%.0f s "
		    "down), detector %s\n",
		    src->name(), o.duration, o.lostRatio, o.restartAt, o.downSeconds,
		    det ? o.model.c_str() : "off");

	const auto t0 = Clock::now();
	auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
	long rssStart = -1, rssMiddle = -1;
	uint64_t processed = 0, processedSteady = 0, detections = 0, errors = 0;
	long allocSteady = 0; // operator new calls outside the restart window
	const long allocAtStart = gAllocations.load();
	bool restarted = false, backAfterRestart = false;
	double killedAt = 0, camUpAt = 0, backAt = 0;
	double nextReport = 60;
	Frame frame;
	while (seconds() < o.duration) {
		if (!restarted && seconds() >= o.restartAt) {
			rssMiddle = rssKiB();
			fake.kill();
			killedAt = seconds();
			restarted = true;
		}
		if (restarted && !fake.running() && seconds() >= killedAt + o.downSeconds) {
			if (!fake.start(o.address, o.lostRatio, why)) {
				std::fprintf(stderr, "soak_aravis: restart failed: %s\n", why.c_str());
				return 1;
			}
			camUpAt = seconds();
		}
		const long before = gAllocations.load();
		st = src->next(frame, 500);
		if (st.ok()) {
			if (det) {
				Detections d;
				if (det->detect(frame.image, d).ok())
					detections += static_cast<uint64_t>(d.count);
				else
					errors++;
			}
			processed++;
			if (rssStart < 0 && processed == 25)
				rssStart = rssKiB();
			// Back: the first frame of the new connection (frames queued before the
			// kill still come out of the old one first).
			if (restarted && !backAfterRestart && src->stats().restarts > 0) {
				backAfterRestart = true;
				backAt = seconds();
			}
		} else if (st.code() != ErrorCode::Timeout) {
			std::fprintf(stderr, "soak_aravis: %s\n", st.message());
			return 1;
		}
		// Steady state: away from start-up and from kill .. first frame after the restart.
		const bool inRestart = restarted && !backAfterRestart;
		if (st.ok() && processed > 25 && !inRestart && !(backAfterRestart && seconds() < backAt + 1)) {
			allocSteady += gAllocations.load() - before;
			processedSteady++;
		}
		if (seconds() >= nextReport) {
			const SourceStats s = src->stats();
			std::printf("  %5.0f s: processed %llu, dropped %llu, incomplete %llu, timeouts %llu, "
				    "restarts %llu, RSS %ld KiB\n",
				    seconds(), (unsigned long long)processed, (unsigned long long)s.dropped,
				    (unsigned long long)s.incomplete, (unsigned long long)s.timeouts,
				    (unsigned long long)s.restarts, rssKiB());
			std::fflush(stdout);
			nextReport += 60;
		}
	}
	const long rssEnd = rssKiB();
	const long allocTotal = gAllocations.load() - allocAtStart;
	const SourceStats s = src->stats();
	const AravisStats t = src->transportStats();
	src->stop();
	fake.kill();
	std::printf("frames processed         %llu (%.1f fps), detections %llu, detect errors %llu\n",
		    (unsigned long long)processed, processed / o.duration, (unsigned long long)detections,
		    (unsigned long long)errors);
	std::printf("delivered / dropped      %llu / %llu (of which never seen %llu; Aravis's "
		    "n_underruns %llu)\n",
		    (unsigned long long)s.delivered, (unsigned long long)s.dropped,
		    (unsigned long long)t.unseenFrames, (unsigned long long)t.underruns);
	std::printf("incomplete               %llu: missing packets %llu, frame timeout %llu, other %llu "
		    "(Aravis's n_missing_frames %llu)\n",
		    (unsigned long long)s.incomplete, (unsigned long long)t.incompleteMissingPackets,
		    (unsigned long long)t.incompleteTimeout, (unsigned long long)t.incompleteOther,
		    (unsigned long long)t.missingFrames);
	std::printf("packets                  missing %llu, resent %llu\n",
		    (unsigned long long)t.missingPackets, (unsigned long long)t.resentPackets);
	std::printf("timeouts / restarts      %llu / %llu (losses noticed %llu)\n",
		    (unsigned long long)s.timeouts, (unsigned long long)s.restarts,
		    (unsigned long long)t.lostEvents);
	std::printf("RSS start/middle/end     %ld / %ld / %ld KiB\n", rssStart, rssMiddle, rssEnd);
	std::printf("operator new per frame   %.4f (%ld calls over %llu steady-state frames)\n",
		    processedSteady ? static_cast<double>(allocSteady) / processedSteady : 0.0, allocSteady,
		    (unsigned long long)processedSteady);
	std::printf("operator new, whole loop %ld calls (start-up and the reconnection included)\n",
		    allocTotal);
	if (restarted)
		std::printf("restart                  killed at %.1f s, camera up at %.1f s, first frame at "
			    "%.1f s: %.2f s after the kill, %.2f s after the camera was back\n",
			    killedAt, camUpAt, backAt, backAt - killedAt, backAt - camUpAt);
	src.reset();
	arv_shutdown();
	return 0;
}
