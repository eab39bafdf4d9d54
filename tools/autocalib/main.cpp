// SPDX-License-Identifier: BSD-2-Clause
// calped-autocalib: runs the generic detector over a stretch of frames, collects the foot
// and head points of confident whole detections and fits the camera (self_calibration.h).
// Writes OpenCV YAML only when the fit succeeds. See docs/calibration.md.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <calped/calped.h>
#include <calped/self_calibration.h>

#include "cli_error.h"
#include "detector_options.h"
#include "file_io.h"
#include "frame_list.h"
#include "image_io.h"
#include "program.h"
#include "video_pipe.h"

namespace calped::apps {

namespace {

const ProgramInfo kProgram = {
	"calped-autocalib",
	"usage: calped-autocalib --model BLOB (--frames DIR | --video FILE) [--person-height M]\n"
	"                        [--max-frames N] [--min-score S] [--principal-point U,V]\n"
	"                        [--resize R] [--compare-to FILE] [--quiet] -o camera.yaml\n"
	"\n"
	"Estimates focal length, tilt, roll and height of a fixed camera from the people the\n"
	"generic detector finds, and writes OpenCV YAML that --calib reads (docs/calibration.md).\n"
	"Not estimated: lens distortion (none), principal point (the image centre unless given),\n"
	"pixel aspect (square), the camera's position and heading on the ground.\n"
	"\n"
	"options:\n",
	"\n"
	"exit status: 0 calibrated, 1 cannot calibrate (the verdict says why; no file written)\n"
	"or runtime error, 2 usage error\n",
};

const std::vector<OptionSpec> kOptions = {
	{ "model", "BLOB", "the calped model blob (calped-convert)" },
	{ "frames", "DIR", "the frames: a folder of images, taken in name order" },
	{ "video", "FILE", "the frames: a video decoded by ffmpeg" },
	{ "output", "FILE", "write the camera to FILE (OpenCV YAML, unit m)", 'o' },
	{ "person-height", "M", "mean height of a detection's box, metres (default 1.7)" },
	{ "max-frames", "N", "use at most the first N frames (default 300)" },
	{ "min-score", "S", "collect detections scoring at least S (default 60)" },
	{ "principal-point", "U,V", "principal point, pixels (default the image centre)" },
	{ "resize", "R", "detector input resize, 0 < R <= 8 (default 1; PETS needs 2)" },
	{ "compare-to", "FILE", "a reference calibration: print the estimate's errors against it" },
	{ "quiet", nullptr, "print only the verdict and errors" },
};

struct Options {
	std::string model, frames, video, output, compareTo;
	double personHeight = 1.7, minScore = 60, resize = 1;
	double principalU = -1, principalV = -1;
	long maxFrames = 300;
	bool quiet = false;
};

int fail(int code, const std::string &message)
{
	return cliFail(kProgram.name, code, message);
}

int parseOptions(int argc, char **argv, Options &opt)
{
	ParsedArgs args;
	const int rc = parseCommandLine(kProgram, kOptions, false, argc, argv, args);
	if (rc >= 0)
		return rc;
	std::string error;
	for (const ParsedOption &o : args.options) {
		const std::string &n = o.name;
		bool ok = true;
		if (n == "model")
			ok = nonEmpty(o, "a file name", opt.model, error);
		else if (n == "frames")
			ok = nonEmpty(o, "a folder", opt.frames, error);
		else if (n == "video")
			ok = nonEmpty(o, "a file name", opt.video, error);
		else if (n == "output")
			ok = nonEmpty(o, "a file name", opt.output, error);
		else if (n == "compare-to")
			ok = nonEmpty(o, "a file name", opt.compareTo, error);
		else if (n == "person-height")
			ok = numberIn(o, 0.5, true, 3.0, opt.personHeight, error);
		else if (n == "min-score")
			ok = numberIn(o, -1e9, false, 1e9, opt.minScore, error);
		else if (n == "resize")
			ok = numberIn(o, 0, true, 8, opt.resize, error);
		else if (n == "max-frames")
			ok = wholeIn(o, 1, 1000000000L, opt.maxFrames, error);
		else if (n == "quiet")
			opt.quiet = true;
		else if (n == "principal-point") {
			const size_t comma = o.value.find(',');
			ok = comma != std::string::npos &&
			     parseNumber(o.value.substr(0, comma), opt.principalU) &&
			     parseNumber(o.value.substr(comma + 1), opt.principalV) && opt.principalU >= 0 &&
			     opt.principalV >= 0;
			if (!ok)
				error = badValue(o, "U,V with both >= 0");
		}
		if (!ok)
			return usageError(kProgram, error);
	}
	if (opt.model.empty())
		return usageError(kProgram, "--model is required");
	if (opt.frames.empty() == opt.video.empty())
		return usageError(kProgram, "give exactly one of --frames DIR and --video FILE");
	if (opt.output.empty())
		return usageError(kProgram, "-o FILE is required (where the camera goes)");
	return -1;
}

void printParameters(const char *label, const CameraParameters &p)
{
	std::fprintf(stderr, "%s: focal %.1f px, tilt %.2f deg, roll %.2f deg, height %.3f m, horizon row %.1f\n",
		     label, p.focal, p.tilt * 180 / M_PI, p.roll * 180 / M_PI, p.height, p.horizonRow);
}

int run(const Options &opt)
{
	std::string error;
	Model model;
	if (!loadModelFile(opt.model, model, error))
		return fail(kExitRuntime, error);

	std::vector<std::string> files;
	int width = 0, height = 0;
	ports::ImageDecoder decoder;
	if (!opt.video.empty()) {
		const Status st = ports::probeVideo(opt.video, width, height);
		if (!st.ok())
			return fail(kExitRuntime, st.message());
	} else {
		if (!listFrames({ opt.frames }, files, error))
			return fail(kExitRuntime, error);
		if (files.size() > size_t(opt.maxFrames))
			files.resize(size_t(opt.maxFrames));
		if (!decoder.probe(files[0], width, height, error))
			return fail(kExitRuntime, error);
	}

	DetectorConfig config;
	config.maxWidth = width;
	config.maxHeight = height;
	config.resize = opt.resize;
	config.method = DetectionMethod::Generic;
	std::unique_ptr<Detector> detector;
	Status st = Detector::create(model, config, detector);
	if (!st.ok())
		return fail(kExitRuntime, "cannot create the detector for " + std::to_string(width) + "x" +
						  std::to_string(height) + " frames: " + st.message());

	SelfCalibrationConfig sc;
	sc.minScore = float(opt.minScore);
	sc.personHeight = opt.personHeight;
	sc.principalU = opt.principalU;
	sc.principalV = opt.principalV;
	SelfCalibrator calibrator(sc);
	if (!calibrator.status().ok())
		return fail(kExitRuntime, calibrator.status().message());

	ports::RgbImage image;
	ports::VideoPipe pipe;
	if (!opt.video.empty()) {
		st = pipe.open(opt.video, width, height);
		if (!st.ok())
			return fail(kExitRuntime, st.message());
		image.width = width;
		image.height = height;
		image.pixels.resize(size_t(width) * height * 3);
	}
	long frame = 0;
	for (; frame < opt.maxFrames; frame++) {
		if (!opt.video.empty()) {
			st = pipe.read(image.pixels.data());
			if (st.code() == ErrorCode::EndOfStream)
				break;
			if (!st.ok())
				return fail(kExitRuntime, st.message());
		} else {
			if (size_t(frame) >= files.size())
				break;
			if (!decoder.decode(files[size_t(frame)], image, error))
				return fail(kExitRuntime, error);
			if (image.width != width || image.height != height)
				return fail(kExitRuntime, files[size_t(frame)] + ": frame size " +
								  std::to_string(image.width) + "x" + std::to_string(image.height) +
								  " differs from the first frame's (a fixed camera has one size)");
		}
		Detections dets;
		st = detector->detect(ImageView::rgb8(image.pixels.data(), image.width, image.height), dets);
		if (!st.ok() && st.code() != ErrorCode::ImageTooSmall)
			return fail(kExitRuntime, "frame " + std::to_string(frame + 1) + ": " + st.message());
		if (st.ok())
			calibrator.add(dets.items, size_t(dets.count), image.width, image.height,
				       uint64_t(frame));
	}
	pipe.close();

	SelfCalibrationResult result;
	const SelfCalibrationVerdict verdict = calibrator.estimate(result);
	if (verdict != SelfCalibrationVerdict::Ok)
		return fail(kExitRuntime, std::string("cannot calibrate (") + selfCalibrationVerdictName(verdict) +
						  ", " + std::to_string(frame) + " frames): " + result.message +
						  "; no camera written");

	char summary[640];
	std::snprintf(summary, sizeof(summary),
		      "calped-autocalib: %ld frames, %d observations, %d inliers, residual %.3f (relative height)\n"
		      "focal %.1f +- %.1f px, tilt %.2f +- %.2f deg, roll %.2f +- %.2f deg, height %.3f +- %.3f m\n"
		      "horizon row %.1f at column %.1f; principal point (%.1f, %.1f) assumed, square pixels,\n"
		      "no lens distortion; mean box height %.2f m assumed (the height scales with it)",
		      frame, result.observations, result.inliers, result.residual, result.focal.value,
		      result.focal.sd, result.tilt.value * 180 / M_PI, result.tilt.sd * 180 / M_PI,
		      result.roll.value * 180 / M_PI, result.roll.sd * 180 / M_PI, result.height.value,
		      result.height.sd, result.horizonRow, result.principalU, result.principalU,
		      result.principalV, opt.personHeight);
	std::string yaml;
	st = formatOpenCvYaml(result.camera, summary, yaml);
	if (!st.ok())
		return fail(kExitRuntime, st.message());
	if (!writeTextFile(opt.output, yaml, error))
		return fail(kExitRuntime, error);
	std::fprintf(stderr, "%s\n", summary);
	if (!result.message.empty() && !opt.quiet)
		std::fprintf(stderr, "calped-autocalib: %s; wrote %s\n", result.message.c_str(), opt.output.c_str());

	if (!opt.compareTo.empty()) {
		CameraModel reference;
		if (!loadCalibrationFile(opt.compareTo, reference, error))
			return fail(kExitRuntime, error);
		CameraParameters ref, est;
		cameraParameters(reference, result.principalU, ref);
		cameraParameters(result.camera, result.principalU, est);
		printParameters("reference", ref);
		printParameters("estimate ", est);
		std::fprintf(stderr,
			     "error: focal %+.1f%%, tilt %+.2f deg, height %+.1f%%, horizon row %+.1f px\n",
			     100 * (est.focal / ref.focal - 1), (est.tilt - ref.tilt) * 180 / M_PI,
			     100 * (est.height / ref.height - 1), est.horizonRow - ref.horizonRow);
	}
	return 0;
}

} // namespace

} // namespace calped::apps

int main(int argc, char **argv)
{
	using namespace calped::apps;
	Options opt;
	const int rc = parseOptions(argc, argv, opt);
	if (rc >= 0)
		return rc;
	return runGuarded(kProgram.name, [&] { return run(opt); });
}
