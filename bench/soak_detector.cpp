// SPDX-License-Identifier: BSD-2-Clause
// Soak: the calibrated detector over a folder of frames, looped to --total frames (default
// 10,000), watching memory. Every frame is decoded into memory first; then each detect()
// runs with an allocation counter on and RSS (/proc/self/statm) is sampled at the start,
// after warm-up, in the middle, at the end and every --every frames. The verdict: RSS at
// the end within 1% of the value after warm-up, and no heap allocation in the per-frame
// path. Usage (docs/benchmarks.md):
//   soak_detector --model BLOB --frames DIR --calib FILE [--total N] [--resize R]
//                 [--warmup N] [--every N] [--count N] [--generic] [--pyramid] [--threads N]
// (--pyramid: the default configuration, resize inside the pyramid and placed levels;
// without it the frame is resized first with the toolbox's octaves, as the soak always ran)
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <new>
#include <string>
#include <unistd.h>
#include <vector>

#include <calped/calped.h>

#include "detector_options.h"

#include "test_data.h"

// --- Counting allocator. With glibc and no sanitizer, malloc itself is counted (operator
// new, aligned new and any C allocation go through it); otherwise operator new is. ---
namespace {
std::atomic<bool> counting{ false };
std::atomic<long> allocations{ 0 };

inline void countOne()
{
	if (counting.load(std::memory_order_relaxed))
		allocations.fetch_add(1, std::memory_order_relaxed);
}
} // namespace

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define CALPED_SOAK_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CALPED_SOAK_SANITIZED 1
#endif

#if defined(__GLIBC__) && !defined(CALPED_SOAK_SANITIZED)
#define CALPED_SOAK_COUNTS_MALLOC 1
extern "C" {
void *__libc_malloc(size_t size);
void *__libc_calloc(size_t count, size_t size);
void *__libc_realloc(void *p, size_t size);
void *__libc_memalign(size_t alignment, size_t size);
void __libc_free(void *p);

void *malloc(size_t size)
{
	countOne();
	return __libc_malloc(size);
}
void *calloc(size_t count, size_t size)
{
	countOne();
	return __libc_calloc(count, size);
}
void *realloc(void *p, size_t size)
{
	countOne();
	return __libc_realloc(p, size);
}
void *aligned_alloc(size_t alignment, size_t size)
{
	countOne();
	return __libc_memalign(alignment, size);
}
void *memalign(size_t alignment, size_t size)
{
	countOne();
	return __libc_memalign(alignment, size);
}
int posix_memalign(void **out, size_t alignment, size_t size)
{
	countOne();
	void *p = __libc_memalign(alignment, size);
	if (!p)
		return ENOMEM;
	*out = p;
	return 0;
}
void free(void *p)
{
	__libc_free(p);
}
}
#else
void *operator new(size_t size)
{
	countOne();
	if (void *p = std::malloc(size ? size : 1))
		return p;
	throw std::bad_alloc();
}
void *operator new[](size_t size)
{
	return operator new(size);
}
void operator delete(void *p) noexcept
{
	std::free(p);
}
void operator delete[](void *p) noexcept
{
	std::free(p);
}
void operator delete(void *p, size_t) noexcept
{
	std::free(p);
}
void operator delete[](void *p, size_t) noexcept
{
	std::free(p);
}
#endif

using namespace calped;

namespace {

// Resident set size in bytes, read without allocating (the counter may be on).
long residentBytes()
{
	char buffer[128];
	const int fd = open("/proc/self/statm", O_RDONLY);
	if (fd < 0)
		return -1;
	const ssize_t n = read(fd, buffer, sizeof(buffer) - 1);
	close(fd);
	if (n <= 0)
		return -1;
	buffer[n] = '\0';
	const char *p = std::strchr(buffer, ' '); // skip the total size
	return p ? std::strtol(p + 1, nullptr, 10) * sysconf(_SC_PAGESIZE) : -1;
}

double mib(long bytes)
{
	return bytes / (1024.0 * 1024.0);
}

int usage()
{
	std::fprintf(stderr,
		     "usage: soak_detector --model BLOB --frames DIR --calib FILE [--total N] "
		     "[--resize R] [--warmup N] [--every N] [--count N] [--generic] [--pyramid] "
		     "[--threads N]\n");
	return 2;
}

struct Options {
	std::string model, frames, calib;
	long total = 10000, warmup = 100, every = 1000;
	int count = 0; // frames to load, 0 = all
	double resize = 1.0;
	bool generic = false;
	bool pyramid = false; // --pyramid: the default configuration (resize in the pyramid, placed levels)
	int threads = 1;      // --threads N: DetectorConfig::threads
};

bool parse(int argc, char **argv, Options &o)
{
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		if (a == "--generic" || a == "--pyramid") {
			(a == "--generic" ? o.generic : o.pyramid) = true;
			continue;
		}
		if (i + 1 >= argc)
			return false;
		const char *v = argv[++i];
		if (a == "--model")
			o.model = v;
		else if (a == "--frames")
			o.frames = v;
		else if (a == "--calib")
			o.calib = v;
		else if (a == "--total")
			o.total = std::atol(v);
		else if (a == "--warmup")
			o.warmup = std::atol(v);
		else if (a == "--every")
			o.every = std::atol(v);
		else if (a == "--count")
			o.count = std::atoi(v);
		else if (a == "--resize")
			o.resize = std::atof(v);
		else if (a == "--threads")
			o.threads = std::atoi(v);
		else
			return false;
	}
	return !o.model.empty() && !o.frames.empty() && !o.calib.empty() && o.total > 0 &&
	       o.warmup >= 0 && o.warmup < o.total && o.every > 0 && o.count >= 0 &&
	       o.resize > 0;
}

} // namespace

int main(int argc, char **argv)
{
	Options opt;
	if (!parse(argc, argv, opt))
		return usage();
	const long rssStart = residentBytes();

	std::vector<uint8_t> bytes;
	Model model;
	if (!test::readFile(opt.model, bytes)) {
		std::fprintf(stderr, "soak_detector: cannot read %s\n", opt.model.c_str());
		return 1;
	}
	Status st = loadModel(bytes.data(), bytes.size(), model);
	if (!st.ok()) {
		std::fprintf(stderr, "soak_detector: %s: %s\n", opt.model.c_str(), st.message());
		return 1;
	}
	if (!test::readFile(opt.calib, bytes)) {
		std::fprintf(stderr, "soak_detector: cannot read %s\n", opt.calib.c_str());
		return 1;
	}
	CameraModel camera;
	st = loadCalibration(reinterpret_cast<const char *>(bytes.data()), bytes.size(),
			     opt.calib.c_str(), camera);
	if (!st.ok()) {
		std::fprintf(stderr, "soak_detector: %s\n", st.message());
		return 1;
	}

	// Every frame decoded once, up front: the loop below only reads memory.
	std::vector<std::string> names;
	if (DIR *d = opendir(opt.frames.c_str())) {
		while (dirent *e = readdir(d))
			if (std::strstr(e->d_name, ".png"))
				names.push_back(opt.frames + "/" + e->d_name);
		closedir(d);
	}
	std::sort(names.begin(), names.end());
	if (opt.count > 0 && names.size() > size_t(opt.count))
		names.resize(opt.count);
	std::vector<test::RgbImage> frames(names.size());
	for (size_t i = 0; i < names.size(); i++) {
		if (!test::loadRgb(names[i], frames[i]) || frames[i].width != frames[0].width ||
		    frames[i].height != frames[0].height) {
			std::fprintf(stderr, "soak_detector: cannot decode %s (or its size differs)\n",
				     names[i].c_str());
			return 1;
		}
	}
	if (frames.empty()) {
		std::fprintf(stderr, "soak_detector: no PNG frames in %s\n", opt.frames.c_str());
		return 1;
	}
	const long rssFrames = residentBytes();

	// The programs' DetectorConfig (tools/common); the soak keeps resizing the frame first
	// with the toolbox's octaves, as it always ran, unless --pyramid.
	apps::DetectorOptions detectorOptions;
	detectorOptions.calibPath = opt.calib;
	detectorOptions.method = opt.generic ? apps::MethodChoice::Generic : apps::MethodChoice::Calibrated;
	detectorOptions.resize = opt.resize;
	detectorOptions.threads = opt.threads;
	if (!opt.pyramid) {
		detectorOptions.resizeAt = apps::ResizeChoice::Frame;
		detectorOptions.levels = apps::LevelsChoice::Toolbox;
	}
	const DetectorConfig cfg =
		apps::makeDetectorConfig(detectorOptions, frames[0].width, frames[0].height, &camera);
	std::unique_ptr<Detector> det;
	st = Detector::create(model, cfg, det);
	if (!st.ok()) {
		std::fprintf(stderr, "soak_detector: %s\n", st.message());
		return 1;
	}
	const long rssCreated = residentBytes();

	// The counter must see an allocation, or "zero per frame" would prove nothing.
	allocations.store(0);
	counting.store(true);
	std::vector<int> *probe = new std::vector<int>(64);
	counting.store(false);
	delete probe;
	if (allocations.load() < 2) {
		std::fprintf(stderr, "soak_detector: the allocation counter does not work\n");
		return 1;
	}

	std::printf("soak: %s detector, %zu frames %dx%d in memory, resize %.2f, %ld frames "
		    "(warm-up %ld), sampling every %ld; counting %s (self-check saw %ld)\n",
		    opt.generic ? "generic" : "calibrated", frames.size(), frames[0].width,
		    frames[0].height, opt.resize, opt.total, opt.warmup, opt.every,
#ifdef CALPED_SOAK_COUNTS_MALLOC
		    "malloc, calloc, realloc and aligned allocations"
#else
		    "operator new"
#endif
		    ,
		    allocations.load());
	std::printf("RSS start %.1f MiB, frames loaded %.1f MiB, detector created %.1f MiB\n",
		    mib(rssStart), mib(rssFrames), mib(rssCreated));
	std::printf("%8s %10s %12s %12s %10s\n", "frame", "RSS MiB", "detections", "allocations",
		    "ms/frame");

	long rssWarm = 0, rssMiddle = 0, rssMin = 0, rssMax = 0;
	long allocWarmup = 0, allocAfter = 0, failures = 0;
	unsigned long long detections = 0, windows = 0;
	double msTotal = 0;
	Detections out;
	const auto start = std::chrono::steady_clock::now();
	for (long k = 0; k < opt.total; k++) {
		const test::RgbImage &f = frames[static_cast<size_t>(k) % frames.size()];
		// The per-frame path: a view of the frame, detect, its result.
		allocations.store(0, std::memory_order_relaxed);
		counting.store(true);
		st = det->detect(ImageView::rgb8(f.pixels.data(), f.width, f.height), out);
		const long frameDetections = out.count;
		counting.store(false);
		const long frameAllocations = allocations.load(std::memory_order_relaxed);
		(k < opt.warmup ? allocWarmup : allocAfter) += frameAllocations;
		if (!st.ok()) {
			failures++;
			if (failures <= 5)
				std::fprintf(stderr, "soak_detector: frame %ld: %s\n", k + 1, st.message());
		}
		detections += static_cast<unsigned long long>(frameDetections);
		windows += det->lastStats().windows;
		msTotal += det->lastStats().msTotal;

		const long done = k + 1;
		if (done == opt.warmup || done == opt.total / 2 || done % opt.every == 0 ||
		    done == opt.total) {
			const long rss = residentBytes();
			if (done == opt.warmup)
				rssWarm = rss;
			if (done == opt.total / 2)
				rssMiddle = rss;
			if (done >= opt.warmup) {
				rssMin = rssMin ? std::min(rssMin, rss) : rss;
				rssMax = std::max(rssMax, rss);
			}
			std::printf("%8ld %10.2f %12llu %12ld %10.2f\n", done, mib(rss), detections,
				    allocWarmup + allocAfter, msTotal / done);
			std::fflush(stdout);
		}
	}
	const double seconds =
		std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	const long rssEnd = residentBytes();
	if (opt.warmup == 0)
		rssWarm = rssCreated;

	const double growth = rssWarm > 0 ? 100.0 * (rssEnd - rssWarm) / rssWarm : 0;
	const bool rssFlat = rssEnd <= rssWarm + rssWarm / 100;
	const bool noAllocations = allocWarmup + allocAfter == 0;
	std::printf("\nframes processed     %ld (%zu distinct, %.1f passes), %ld failed\n", opt.total,
		    frames.size(), double(opt.total) / frames.size(), failures);
	std::printf("detections          %llu (%.2f per frame), %.0f windows per frame\n",
		    detections, double(detections) / opt.total, double(windows) / opt.total);
	std::printf("time                %.1f s wall, %.2f ms per frame (detector's own clock)\n",
		    seconds, msTotal / opt.total);
	std::printf("allocations         %ld in warm-up (%ld frames), %ld after (%.4f per frame)\n",
		    allocWarmup, opt.warmup, allocAfter,
		    double(allocAfter) / double(opt.total - opt.warmup));
	std::printf("RSS MiB             start %.2f, after warm-up %.2f, middle %.2f, end %.2f "
		    "(after warm-up: min %.2f, max %.2f)\n",
		    mib(rssStart), mib(rssWarm), mib(rssMiddle), mib(rssEnd), mib(rssMin),
		    mib(rssMax));
	std::printf("RSS end - warm-up   %+ld KiB (%+.3f%%)\n", (rssEnd - rssWarm) / 1024, growth);
	std::printf("verdict             %s: RSS %s (end within 1%% of after warm-up), "
		    "per-frame allocations %s\n",
		    rssFlat && noAllocations && failures == 0 ? "PASS" : "FAIL",
		    rssFlat ? "flat" : "GREW", noAllocations ? "zero" : "NOT ZERO");
	return rssFlat && noAllocations && failures == 0 ? 0 : 1;
}
