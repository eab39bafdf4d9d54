// SPDX-License-Identifier: BSD-2-Clause
// Per-frame time of the generic detector on a folder of frames, one core: frames are
// decoded first, then each is detected `--repeat` times; prints median and mean per
// stage. Usage:
//   bench_detect --model BLOB --frames DIR [--resize R [--resize-in-pyramid]] [--first F]
//                [--count N] [--repeat K] [--calib FILE [--calibrated [--calibrated-pyramid]]]
//                [--reject-static] [--format NAME]
// --first: the F-th frame (1-based, in name order) is the first. --reject-static: static-
// scene rejection (and its gate of the sparse grid), whose background takes 50 frames.
// --format converts the decoded frames to a camera pixel format first (NV12, YUYV,
// BayerRGGB8, ...: docs/pixel-formats.md), so the detector's input conversion is timed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <string>
#include <vector>

#include <calped/calped.h>

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

int usage()
{
	std::fprintf(stderr, "usage: bench_detect --model BLOB --frames DIR [--resize R [--resize-in-pyramid]] [--first F] [--count N] "
			     "[--repeat K] [--calib FILE [--calibrated [--calibrated-pyramid]]] [--reject-static] [--format NAME]\n");
	return 2;
}

} // namespace

int main(int argc, char **argv)
{
	std::string modelPath, framesDir, calibPath, formatName = "RGB8";
	double resize = 1.0;
	int first = 1, count = 50, repeat = 1; // first: 1-based, in name order
	bool calibrated = false, resizeInPyramid = false, calibratedPyramid = false, rejectStatic = false;
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		if (a == "--reject-static") {
			rejectStatic = true;
			continue;
		}
		if (a == "--calibrated" || a == "--resize-in-pyramid" || a == "--calibrated-pyramid") {
			(a == "--calibrated" ? calibrated : a == "--resize-in-pyramid" ? resizeInPyramid : calibratedPyramid) = true;
			continue;
		}
		if (i + 1 >= argc)
			return usage();
		if (a == "--model")
			modelPath = argv[++i];
		else if (a == "--frames")
			framesDir = argv[++i];
		else if (a == "--resize")
			resize = std::atof(argv[++i]);
		else if (a == "--first")
			first = std::atoi(argv[++i]);
		else if (a == "--count")
			count = std::atoi(argv[++i]);
		else if (a == "--repeat")
			repeat = std::atoi(argv[++i]);
		else if (a == "--calib")
			calibPath = argv[++i];
		else if (a == "--format")
			formatName = argv[++i];
		else
			return usage();
	}
	if (modelPath.empty() || framesDir.empty() || first < 1 || count < 1 || repeat < 1)
		return usage();
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

	std::vector<uint8_t> blob;
	Model model;
	if (!test::readFile(modelPath, blob)) {
		std::fprintf(stderr, "bench_detect: cannot read %s\n", modelPath.c_str());
		return 1;
	}
	Status st = loadModel(blob.data(), blob.size(), model);
	if (!st.ok()) {
		std::fprintf(stderr, "bench_detect: %s: %s\n", modelPath.c_str(), st.message());
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

	DetectorConfig cfg;
	cfg.maxWidth = frames[0].width;
	cfg.maxHeight = frames[0].height;
	cfg.resize = resize;
	cfg.resizeAt = resizeInPyramid ? ResizeAt::Pyramid : ResizeAt::Frame;
	if (rejectStatic) // fixed camera: frames must be consecutive
		cfg.staticRejection = StaticRejection();
	CameraModel camera;
	if (!calibPath.empty()) {
		std::vector<uint8_t> text;
		if (!test::readFile(calibPath, text)) {
			std::fprintf(stderr, "bench_detect: cannot read %s\n", calibPath.c_str());
			return 1;
		}
		st = loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(),
				     calibPath.c_str(), camera);
		if (!st.ok()) {
			std::fprintf(stderr, "bench_detect: %s\n", st.message());
			return 1;
		}
		cfg.camera = &camera;
	}
	cfg.method = calibrated ? DetectionMethod::Calibrated : DetectionMethod::Generic;
	if (calibrated) {
		CalibratedSettings cal;
		cal.levels = calibratedPyramid ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cfg.calibrated = cal;
	}
	std::unique_ptr<Detector> det;
	st = Detector::create(model, cfg, det);
	if (!st.ok()) {
		std::fprintf(stderr, "bench_detect: %s\n", st.message());
		return 1;
	}

	std::vector<double> total, channels, approx, classify, nms, resizeMs;
	uint64_t windows = 0, detections = 0;
	int levels = 0, computed = 0;
	Detections out;
	det->detect(inputs[0].view(), out); // warm-up
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
	std::printf("%s %s, frames %zu x %d, %dx%d, resize %.2f: %d levels (%d computed), %.0f windows/frame, %.2f detections/frame\n",
		    calibrated ? "calibrated" : "generic", pixelFormatName(format), frames.size(), repeat, frames[0].width,
		    frames[0].height, resize, levels, computed,
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
