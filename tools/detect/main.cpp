// SPDX-License-Identifier: BSD-2-Clause
// calped-detect: runs the detector over image files or folders and writes CSV, JSON Lines
// and overlay images. See docs/cli.md.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include <calped/calped.h>

#include "cli_error.h"
#include "file_io.h"
#include "frame_list.h"
#include "image_io.h"
#include "options.h"
#include "overlay.h"
#include "progress.h"
#include "writers.h"

using calped::kExitRuntime;
using calped::kExitUsage;

namespace calped::detect_tool {

namespace {

int fail(int code, std::string message)
{
	return cliFail("calped-detect", code, std::move(message));
}

std::string frameLabel(long frame, const std::string &path)
{
	return "frame " + std::to_string(frame) + " (" + path + ")";
}

std::string overlayPath(const std::string &dir, long frame)
{
	char name[32];
	std::snprintf(name, sizeof(name), "%06ld.png", frame);
	return dir + "/" + name;
}

int run(const Options &opt)
{
	std::string error;

	std::vector<std::string> frames;
	if (!listFrames(opt.inputs, frames, error))
		return fail(kExitRuntime, error);
	if (opt.maxFrames > 0 && static_cast<size_t>(opt.maxFrames) < frames.size())
		frames.resize(static_cast<size_t>(opt.maxFrames));

	// Headers only: finds undecodable files before any work and sizes the detector for
	// the largest frame, so frames of mixed sizes all fit.
	int maxW = 0, maxH = 0;
	for (const std::string &path : frames) {
		int w = 0, h = 0;
		if (!probeImage(path, w, h, error))
			return fail(kExitRuntime, error);
		maxW = std::max(maxW, w);
		maxH = std::max(maxH, h);
	}

	std::vector<uint8_t> blob;
	if (!readFile(opt.model, blob, error, "model "))
		return fail(kExitRuntime, error);
	Model model;
	Status st = loadModel(blob.data(), blob.size(), model);
	if (!st.ok())
		return fail(kExitRuntime, "model " + opt.model + ": " + st.message());
	blob = std::vector<uint8_t>();

	DetectorConfig config;
	config.maxWidth = maxW;
	config.maxHeight = maxH;
	config.resize = opt.resize;
	config.resizeAt = opt.resizeInPyramid ? ResizeAt::Pyramid : ResizeAt::Frame;
	if (opt.rejectStatic)
		config.staticRejection = StaticRejection();
	config.nms = !opt.noNms;
	CameraModel camera;
	if (!opt.calibPath.empty()) {
		std::vector<uint8_t> text;
		if (!readFile(opt.calibPath, text, error, "calibration "))
			return fail(kExitRuntime, error);
		st = loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(),
				     opt.calibPath.c_str(), camera);
		if (!st.ok())
			return fail(kExitRuntime, std::string("calibration: ") + st.message());
		config.camera = &camera;
	}
	config.method = opt.calibrated ? DetectionMethod::Calibrated : DetectionMethod::Generic;
	if (opt.calibrated || opt.calibratedPyramid) { // refused with the generic method
		CalibratedSettings cal;
		cal.levels = opt.calibratedPyramid ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cal.minPersonHeight = opt.minHeight;
		cal.maxPersonHeight = opt.maxHeight;
		cal.boxVoting = !opt.noBoxVoting && !opt.noNms;
		cal.scoreRatio = !opt.noNms;
		config.calibrated = cal;
	}
	std::unique_ptr<Detector> detector;
	st = Detector::create(model, config, detector);
	if (!st.ok())
		return fail(kExitRuntime, std::string("cannot set up the detector for ") +
						  std::to_string(maxW) + "x" + std::to_string(maxH) +
						  " frames: " + st.message());

	OutputFile csv, jsonl;
	if (!opt.csvPath.empty()) {
		if (!csv.open(opt.csvPath, error))
			return fail(kExitRuntime, error);
		writeCsvHeader(csv.get());
	}
	if (!opt.jsonlPath.empty() && !jsonl.open(opt.jsonlPath, error))
		return fail(kExitRuntime, error);
	if (!opt.overlayDir.empty() && !makeDirectories(opt.overlayDir, error))
		return fail(kExitRuntime, error);

	RunStats stats(static_cast<long>(frames.size()));
	RgbImage image;
	for (size_t i = 0; i < frames.size(); i++) {
		const long frame = static_cast<long>(i) + 1;
		const std::string &path = frames[i];
		if (!decodeImage(path, image, error))
			return fail(kExitRuntime, error);

		Detections dets;
		st = detector->detect(ImageView::rgb8(image.pixels.data(), image.width, image.height), dets);
		if (st.code() == ErrorCode::ImageTooSmall) {
			// No window fits: the honest answer is "no pedestrians", not a failed run.
			if (!opt.quiet)
				std::fprintf(stderr, "calped-detect: warning: %s is smaller than the model window, no detections\n",
					     frameLabel(frame, path).c_str());
			dets = Detections();
		} else if (!st.ok()) {
			return fail(kExitRuntime, frameLabel(frame, path) + ": " + st.message());
		}
		const double ms = st.ok() ? detector->lastStats().msTotal : 0.0;

		if (csv.isOpen())
			writeCsvRows(csv.get(), frame, dets);
		if (jsonl.isOpen())
			writeJsonlFrame(jsonl.get(), frame, path, ms, dets);
		if (!opt.overlayDir.empty() && (frame - 1) % opt.overlayEvery == 0) {
			if (!writePng(overlayPath(opt.overlayDir, frame), renderOverlay(image, dets), error))
				return fail(kExitRuntime, error);
		}

		stats.addFrame(ms, dets.count);
		if (!opt.quiet && stats.progressDue())
			stats.printProgress();
	}

	if (!csv.close(error) || !jsonl.close(error))
		return fail(kExitRuntime, error);
	if (!opt.quiet)
		stats.printSummary();
	return 0;
}

} // namespace

} // namespace calped::detect_tool

int main(int argc, char **argv)
{
	using namespace calped::detect_tool;

	// A closed pipe on --jsonl - becomes a reported write error instead of a silent death.
	std::signal(SIGPIPE, SIG_IGN);

	Options opt;
	std::string error;
	if (!parseOptions(argc, argv, opt, error))
		return fail(kExitUsage, error);
	if (opt.help) {
		std::fputs(usageText(), stdout);
		return 0;
	}
	return calped::runGuarded("calped-detect", [&] { return run(opt); });
}
