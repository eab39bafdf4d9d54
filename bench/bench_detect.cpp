// SPDX-License-Identifier: BSD-2-Clause
// Per-frame time of the detector on a folder of frames, one core: frames are decoded
// first, then each is detected `--repeat` times; prints median and mean per stage. Usage:
//   bench_detect --frames DIR [--first F] [--count N] [--repeat K] [--format NAME]
//                DETECTOR FLAGS (calped-detect's: --model BLOB [--calib FILE] [--method M]
//                [--resize R] [--resize-at pyramid|frame] [--levels placed|toolbox]
//                [--reject-static] ..., docs/cli.md)
// --first: the F-th frame (1-based, in name order) is the first. --reject-static: static-
// scene rejection (and its gate of the sparse grid), whose background takes 50 frames.
// --format converts the decoded frames to a camera pixel format first (NV12, YUYV,
// BayerRGGB8, ...: docs/pixel-formats.md), so the detector's input conversion is timed.
// --alternate-threads 1,2: one detector per thread count, each frame detected by every one
// in turn (the order rotating from frame to frame), so that this machine's drift in speed
// falls on all alike; prints wall-clock ms per frame and the speed-ups, and fails unless
// every detector's detections are the same as the first's.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "detector_options.h"
#include "program.h"

#include "pixel_formats.h"
#include "test_data.h"

using namespace calped;

namespace {

double median(std::vector<double> v)
{
	if (v.empty())
		return 0;
	std::sort(v.begin(), v.end());
	const size_t n = v.size();
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double mean(const std::vector<double> &v)
{
	double s = 0;
	for (double x : v)
		s += x;
	return v.empty() ? 0 : s / v.size();
}

// "1,2,4" -> {1, 2, 4}; each 1..64.
bool parseThreadList(const std::string &text, std::vector<long> &out, std::string &error)
{
	out.clear();
	size_t at = 0;
	while (at <= text.size()) {
		const size_t comma = std::min(text.find(',', at), text.size());
		long n = 0;
		if (!apps::parseWhole(text.substr(at, comma - at), n) || n < 1 || n > 64) {
			error = "--alternate-threads takes thread counts 1..64 separated by commas, got \"" + text + "\"";
			return false;
		}
		out.push_back(n);
		at = comma + 1;
	}
	return true;
}

bool sameDetections(const Detections &a, const std::vector<Detection> &b)
{
	return size_t(a.count) == b.size() &&
	       (b.empty() || std::memcmp(a.items, b.data(), b.size() * sizeof(Detection)) == 0);
}

// Every frame through every detector in turn; returns the exit status.
int alternate(std::vector<std::unique_ptr<Detector>> &dets, const std::vector<long> &threads,
	      const std::vector<test::FormattedImage> &inputs, long repeat)
{
	using Clock = std::chrono::steady_clock;
	const size_t n = dets.size();
	std::vector<std::vector<double>> ms(n);
	std::vector<double> sum(n, 0.0);
	std::vector<Detection> reference;
	Detections out;
	for (auto &d : dets)
		d->detect(inputs[0].view(), out); // warm-up
	size_t turn = 0, differing = 0;
	for (long r = 0; r < repeat; r++)
		for (const auto &f : inputs) {
			std::vector<bool> same(n, true);
			for (size_t k = 0; k < n; k++) {
				const size_t d = (turn + k) % n;
				const auto t0 = Clock::now();
				const Status st = dets[d]->detect(f.view(), out);
				const double took = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
				if (!st.ok()) {
					std::fprintf(stderr, "bench_detect: %s\n", st.message());
					return 1;
				}
				ms[d].push_back(took);
				sum[d] += took;
				if (k == 0)
					reference.assign(out.begin(), out.end());
				else if (!sameDetections(out, reference))
					same[d] = false;
			}
			differing += size_t(std::count(same.begin(), same.end(), false));
			turn++;
		}
	std::printf("side by side: every frame detected by each thread count in turn (%zu frames)\n\n", turn);
	std::printf("| threads | ms/frame median | ms/frame mean | frames/s | speed-up |\n");
	std::printf("|---:|---:|---:|---:|---:|\n");
	for (size_t d = 0; d < n; d++)
		std::printf("| %ld | %.2f | %.2f | %.1f | %.2fx |\n", threads[d], median(ms[d]), mean(ms[d]),
			    1000.0 * double(turn) / sum[d], sum[0] / sum[d]);
	if (differing) {
		std::printf("\ndetections DIFFER between thread counts on %zu frame runs\n", differing);
		return 1;
	}
	std::printf("\ndetections identical for every thread count on every frame\n");
	return 0;
}

const apps::ProgramInfo kProgram = {
	"bench_detect",
	"usage: bench_detect --model BLOB --frames DIR [options]\n"
	"\n"
	"Times the detector per frame and stage on a folder of PNG frames (docs/benchmarks.md).\n"
	"\n"
	"options:\n",
	"",
};

} // namespace

int main(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> own = {
		{ "frames", "DIR", "the PNG frames, in name order" },
		{ "first", "F", "start at the F-th frame (1-based, default 1)" },
		{ "count", "N", "frames to time (default 50)" },
		{ "repeat", "K", "detect each frame K times (default 1)" },
		{ "alternate-threads", "LIST", "time these thread counts (e.g. 1,2) side by side: every frame\n"
					       "detected by each in turn; fails unless their detections agree" },
		{ "format", "NAME", "convert the frames to this camera pixel format first (NV12, YUYV,\n"
				    "BayerRGGB8, ...; default RGB8), so the input conversion is timed" },
	};
	apps::DetectorOptions options;
	apps::ParsedArgs args;
	const int rc = apps::parseCommandLine(
		kProgram, apps::joinOptions(own, apps::detectorOptionTable(apps::DetectorFlags::All)), false,
		argc, argv, args, [&](const apps::ParsedOption &o, std::string &e) {
			return apps::takeDetectorOption(o, options, e);
		});
	if (rc >= 0)
		return rc;
	std::string framesDir, formatName = "RGB8", error;
	std::vector<long> alternateThreads;
	long first = 1, count = 50, repeat = 1; // first: 1-based, in name order
	for (const apps::ParsedOption &o : args.options) {
		if (o.name == "frames") {
			framesDir = o.value;
		} else if (o.name == "format") {
			formatName = o.value;
		} else if (o.name == "alternate-threads") {
			parseThreadList(o.value, alternateThreads, error);
		} else {
			apps::wholeIn(o, 1, 1000000, o.name == "first" ? first : o.name == "count" ? count : repeat,
				      error);
		}
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (framesDir.empty())
		return apps::usageError(kProgram, "missing --frames DIR (try --help)");
	if (!apps::checkDetectorOptions(options, true, apps::DetectorFlags::All, error))
		return apps::usageError(kProgram, error);
	const bool calibrated = options.calibrated();
	PixelFormat format = PixelFormat::RGB8;
	bool formatKnown = false;
	for (int f = int(PixelFormat::RGB8); f <= int(PixelFormat::BayerBGGR8); f++)
		if (formatName == pixelFormatName(PixelFormat(f))) {
			format = PixelFormat(f);
			formatKnown = true;
		}
	if (!formatKnown) {
		std::fprintf(stderr, "bench_detect: unknown pixel format %s\n", formatName.c_str());
		return 2;
	}

	apps::DetectorInputs loaded;
	if (!apps::loadDetectorInputs(options, loaded, error)) {
		std::fprintf(stderr, "bench_detect: %s\n", error.c_str());
		return 1;
	}

	std::vector<std::string> names;
	if (DIR *d = opendir(framesDir.c_str())) {
		while (dirent *e = readdir(d))
			if (std::strstr(e->d_name, ".png"))
				names.push_back(framesDir + "/" + e->d_name);
		closedir(d);
	}
	std::sort(names.begin(), names.end());
	names.erase(names.begin(), names.begin() + std::min(names.size(), size_t(first - 1)));
	if (names.size() > size_t(count))
		names.resize(count);
	std::vector<test::RgbImage> frames(names.size());
	for (size_t i = 0; i < names.size(); i++)
		if (!test::loadRgb(names[i], frames[i])) {
			std::fprintf(stderr, "bench_detect: cannot decode %s\n", names[i].c_str());
			return 1;
		}
	if (frames.empty()) {
		std::fprintf(stderr, "bench_detect: no PNG frames in %s\n", framesDir.c_str());
		return 1;
	}

	std::vector<test::FormattedImage> inputs;
	for (const auto &f : frames)
		inputs.push_back(test::encodeImage(f.pixels.data(), f.width, f.height, format));

	if (!alternateThreads.empty()) {
		std::vector<std::unique_ptr<Detector>> dets(alternateThreads.size());
		for (size_t d = 0; d < dets.size(); d++) {
			options.threads = alternateThreads[d];
			if (!apps::createDetector(loaded.model, options, frames[0].width, frames[0].height,
						  loaded.hasCamera ? &loaded.camera : nullptr, dets[d], error)) {
				std::fprintf(stderr, "bench_detect: %s\n", error.c_str());
				return 1;
			}
		}
		return alternate(dets, alternateThreads, inputs, repeat);
	}

	// Static rejection (--reject-static) needs consecutive frames of one camera.
	std::unique_ptr<Detector> det;
	std::string resizeNote; // --resize auto (the default with --calib): the resize chosen
	if (!apps::createDetector(loaded.model, options, frames[0].width, frames[0].height,
				  loaded.hasCamera ? &loaded.camera : nullptr, det, error, &resizeNote)) {
		std::fprintf(stderr, "bench_detect: %s\n", error.c_str());
		return 1;
	}

	std::vector<double> total, channels, approx, classify, nms, resizeMs;
	uint64_t windows = 0, detections = 0;
	int levels = 0, computed = 0;
	Detections out;
	Status st = det->detect(inputs[0].view(), out); // warm-up
	for (int r = 0; r < repeat; r++)
		for (const auto &f : inputs) {
			st = det->detect(f.view(), out);
			if (!st.ok()) {
				std::fprintf(stderr, "bench_detect: %s\n", st.message());
				return 1;
			}
			const FrameStats &s = det->lastStats();
			total.push_back(s.msTotal);
			resizeMs.push_back(s.msResize);
			channels.push_back(s.msChannels);
			approx.push_back(s.msApprox);
			classify.push_back(s.msClassify);
			nms.push_back(s.msNms);
			windows += s.windows;
			detections += out.count;
			levels = s.levels;
			computed = s.computedLevels;
		}
	const double n = double(total.size());
	if (!resizeNote.empty())
		std::printf("%s\n", resizeNote.c_str());
	char resizeText[32];
	if (resizeNote.empty())
		std::snprintf(resizeText, sizeof resizeText, "%.2f", options.resize);
	else
		std::snprintf(resizeText, sizeof resizeText, "auto");
	std::printf("%s %s, frames %zu x %ld, %dx%d, resize %s: %d levels (%d computed), %.0f windows/frame, %.2f detections/frame\n",
		    calibrated ? "calibrated" : "generic", pixelFormatName(format), frames.size(), repeat, frames[0].width,
		    frames[0].height, resizeText, levels, computed,
		    windows / n, detections / n);
	std::printf("ms per frame      median   mean\n");
	std::printf("  total          %7.2f %7.2f\n", median(total), mean(total));
	std::printf("  resize         %7.2f %7.2f\n", median(resizeMs), mean(resizeMs));
	std::printf("  channels       %7.2f %7.2f   (colour, gradients, histograms of computed levels)\n", median(channels), mean(channels));
	std::printf("  approx+smooth  %7.2f %7.2f   (approximated levels, smoothing, padding)\n", median(approx), mean(approx));
	std::printf("  classify       %7.2f %7.2f\n", median(classify), mean(classify));
	std::printf("  nms            %7.2f %7.2f\n", median(nms), mean(nms));
	return 0;
}
