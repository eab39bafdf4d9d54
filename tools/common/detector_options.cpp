// SPDX-License-Identifier: BSD-2-Clause
#include "detector_options.h"

#include <algorithm>
#include <cstdio>

#include "file_io.h"

namespace calped::apps {

bool DetectorOptions::calibrated() const
{
	return method == MethodChoice::Calibrated ||
	       (method == MethodChoice::Default && !calibPath.empty());
}

bool DetectorOptions::resizeInPyramid() const
{
	// The pyramid only upscales: below 1 the frame is resized first unless asked otherwise
	// (then checkDetectorOptions refuses it).
	return resizeAt == ResizeChoice::Pyramid || (resizeAt == ResizeChoice::Default && resize >= 1.0);
}

bool DetectorOptions::placedLevels() const
{
	if (!calibrated() || levels == LevelsChoice::Toolbox)
		return false;
	// Placed levels need the frame at its own size: resize 1 or the resize in the pyramid.
	return levels == LevelsChoice::Placed || resizeInPyramid() || resize == 1.0;
}

int DetectorOptions::detectorThreads() const
{
	if (threads > 0)
		return int(threads);
	return recommendedThreads();
}

std::vector<OptionSpec> detectorOptionTable(DetectorFlags which)
{
	std::vector<OptionSpec> t = {
		{ "model", "BLOB", "calped model blob (.cpm, made by calped-convert)" },
		{ "calib", "FILE", "camera calibration (Tsai XML, Town Centre .ci, plain P, OpenCV\n"
				   "YAML); selects the calibrated method unless --method generic;\n"
				   "auto: estimated from the people found (the generic method\n"
				   "runs until then)" },
	};
	if (which == DetectorFlags::All) {
		t.push_back({ "method", "M", "generic or calibrated (default: calibrated with --calib,\n"
					     "generic without; calibrated needs --calib)" });
		t.push_back({ "resize", "R", "upscale by R before detecting, 0 < R <= 8, or auto: the\n"
					     "smallest that shows the smallest plausible person at the\n"
					     "model's size (default: auto with --calib, else 1)" });
		t.push_back({ "range", "M", "calibrated, --resize auto: look for people up to M metres\n"
					    "from the camera (default 30)" });
	}
	t.push_back({ "resize-at", "WHERE", "pyramid (default): the resize inside the feature pyramid\n"
					    "(the toolbox's nOctUp); frame: resize the frame first,\n"
					    "as the thesis does (the default when R < 1)" });
	t.push_back({ "threads", "N", "threads the detector works on, 1..64 (default: the online\n"
				      "cores, at most 4); the detections do not depend on it" });
	t.push_back({ "levels", "L", "calibrated method: placed (default) computes channels at\n"
				     "levels placed among the needed ones; toolbox: the toolbox's\n"
				     "octaves (the default when the frame is resized first)" });
	if (which == DetectorFlags::All) {
		t.push_back({ "reject-static", nullptr, "fixed camera: drop detections on static scene\n"
							"structure (frames of one camera, in order)" });
		t.push_back({ "min-height", "H", "calibrated: smallest plausible person, metres (default 1.4)" });
		t.push_back({ "max-height", "H", "calibrated: tallest plausible person, metres (default 2.2)" });
		t.push_back({ "no-nms", nullptr, "keep every window that passed the cascade" });
		t.push_back({ "no-box-voting", nullptr, "calibrated: keep the best window's box (the thesis's)" });
		t.push_back({ "score-ratio", nullptr, "calibrated: the thesis's second suppression step (score\n"
						  "ratio against overlap; off by default)" });
		t.push_back({ "region-frames", "N", "calibrated: a dense region lives N frames without a\n"
						    "detection (default 3; 1 is the thesis's)" });
		t.push_back({ "min-score", "S", "leave detections scoring below S out of the output" });
	}
	return t;
}

bool takeDetectorOption(const ParsedOption &o, DetectorOptions &out, std::string &error)
{
	error.clear();
	const std::string &n = o.name;
	if (n == "model") {
		nonEmpty(o, "a file name", out.model, error);
	} else if (n == "calib") {
		nonEmpty(o, "a file name", out.calibPath, error);
	} else if (n == "method") {
		if (o.value == "generic" || o.value == "calibrated")
			out.method = o.value == "generic" ? MethodChoice::Generic : MethodChoice::Calibrated;
		else
			error = badValue(o, "generic or calibrated");
	} else if (n == "resize") {
		out.resizeGiven = true;
		out.resizeAuto = o.value == "auto";
		if (!out.resizeAuto)
			numberIn(o, 0, true, 8, out.resize, error);
	} else if (n == "range") {
		numberIn(o, 0, true, 1e4, out.range, error);
		out.rangeGiven = true;
	} else if (n == "resize-at") {
		if (o.value == "pyramid" || o.value == "frame")
			out.resizeAt = o.value == "pyramid" ? ResizeChoice::Pyramid : ResizeChoice::Frame;
		else
			error = badValue(o, "pyramid or frame");
	} else if (n == "levels") {
		if (o.value == "placed" || o.value == "toolbox")
			out.levels = o.value == "placed" ? LevelsChoice::Placed : LevelsChoice::Toolbox;
		else
			error = badValue(o, "placed or toolbox");
	} else if (n == "reject-static") {
		out.rejectStatic = true;
	} else if (n == "min-height" || n == "max-height") {
		double h = 0;
		if (parseNumber(o.value, h) && h > 0 && h < 10) {
			(n == "min-height" ? out.minHeight : out.maxHeight) = h;
			out.heightsGiven = true;
		} else {
			error = badValue(o, "a height in metres, > 0 and < 10");
		}
	} else if (n == "no-nms") {
		out.noNms = true;
	} else if (n == "no-box-voting") {
		out.noBoxVoting = true;
	} else if (n == "score-ratio") {
		out.scoreRatio = true;
	} else if (n == "region-frames") {
		wholeIn(o, 1, 1000, out.regionFrames, error);
	} else if (n == "threads") {
		wholeIn(o, 1, 64, out.threads, error);
	} else if (n == "min-score") {
		if (!parseNumber(o.value, out.minScore))
			error = badValue(o, "a number");
	} else {
		return false;
	}
	return true;
}

bool checkDetectorOptions(DetectorOptions &o, bool requireModel, DetectorFlags which,
			  std::string &error)
{
	if (requireModel && o.model.empty()) {
		error = "missing --model BLOB (try --help)";
		return false;
	}
	if (o.method == MethodChoice::Calibrated && o.calibPath.empty()) {
		error = "--method calibrated needs --calib FILE";
		return false;
	}
	if (o.calibAuto()) {
		if (which != DetectorFlags::All) {
			error = "--calib auto is for calped-detect and the live programs";
			return false;
		}
		if (o.method != MethodChoice::Default) {
			error = "--calib auto runs the generic method, then the calibrated one: no --method";
			return false;
		}
		if (o.levels == LevelsChoice::Toolbox || o.resizeAt == ResizeChoice::Frame) {
			error = "--calib auto: the calibrated method's resize is chosen from the camera, "
				"inside the pyramid with placed levels (no --levels toolbox or --resize-at frame)";
			return false;
		}
		// --resize is the generic method's while collecting; the calibrated method's is
		// chosen from the estimated camera.
		if (!o.resizeGiven || o.resizeAuto)
			o.resize = 2.0;
		o.resizeAuto = false;
	} else if (which == DetectorFlags::All && !o.resizeGiven && o.calibrated()) {
		o.resizeAuto = true;
	}
	if (o.resizeAuto && !o.calibrated()) {
		error = "--resize auto needs a calibration (--calib FILE)";
		return false;
	}
	if (o.rangeGiven && !o.resizeAuto) {
		error = "--range applies to --resize auto only";
		return false;
	}
	if (o.resizeAuto)
		o.resize = 1.0; // chosen by resolveAutoResize(), always >= 1
	if (o.resizeAt == ResizeChoice::Pyramid && o.resize < 1.0) {
		error = "--resize-at pyramid needs --resize >= 1 (the pyramid only upscales); use --resize-at frame";
		return false;
	}
	if (o.levels == LevelsChoice::Placed && !o.resizeInPyramid() && o.resize != 1.0) {
		error = "--levels placed needs the resize inside the pyramid (--resize-at pyramid) or --resize 1";
		return false;
	}
	if (which == DetectorFlags::Eval)
		return true; // calped-eval checks per run (methods and resizes vary)
	if (!o.calibrated()) {
		const char *flag = o.levels != LevelsChoice::Default ? "--levels"
				   : o.heightsGiven            ? "--min-height/--max-height"
				   : o.noBoxVoting             ? "--no-box-voting"
				   : o.scoreRatio              ? "--score-ratio"
				   : o.regionFrames != 0       ? "--region-frames"
							       : nullptr;
		if (flag) {
			error = std::string(flag) + " applies to the calibrated method only (give --calib FILE)";
			return false;
		}
	}
	if (o.minHeight > o.maxHeight) {
		error = "--min-height is above --max-height";
		return false;
	}
	return true;
}

bool loadModelFile(const std::string &path, Model &model, std::string &error)
{
	std::vector<uint8_t> blob;
	if (!readFile(path, blob, error, "model ", kMaxModelFileBytes))
		return false;
	const Status st = loadModel(blob.data(), blob.size(), model);
	if (!st.ok()) {
		error = "model " + path + ": " + st.message();
		return false;
	}
	return true;
}

bool loadCalibrationFile(const std::string &path, CameraModel &camera, std::string &error)
{
	std::vector<uint8_t> text;
	if (!readFile(path, text, error, "calibration ", kMaxCalibrationFileBytes))
		return false;
	const Status st = loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(),
					  path.c_str(), camera);
	if (!st.ok()) {
		error = std::string("calibration: ") + st.message();
		return false;
	}
	return true;
}

bool loadDetectorInputs(const DetectorOptions &options, DetectorInputs &out, std::string &error)
{
	if (!loadModelFile(options.model, out.model, error))
		return false;
	out.hasCamera = !options.calibPath.empty() && !options.calibAuto();
	return !out.hasCamera || loadCalibrationFile(options.calibPath, out.camera, error);
}

DetectorConfig makeDetectorConfig(const DetectorOptions &o, int width, int height,
				  const CameraModel *camera)
{
	DetectorConfig config;
	config.maxWidth = width;
	config.maxHeight = height;
	config.resize = o.resize;
	config.resizeAt = o.resizeInPyramid() ? calped::ResizeAt::Pyramid : calped::ResizeAt::Frame;
	config.method = o.calibrated() ? DetectionMethod::Calibrated : DetectionMethod::Generic;
	config.camera = camera;
	// --no-nms returns every window that passed the cascade: nothing left to vote on.
	config.nms = !o.noNms;
	config.threads = o.detectorThreads();
	if (o.rejectStatic)
		config.staticRejection = StaticRejection();
	if (o.calibrated()) {
		CalibratedSettings cal;
		cal.levels = o.placedLevels() ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cal.minPersonHeight = o.minHeight;
		cal.maxPersonHeight = o.maxHeight;
		cal.boxVoting = !o.noBoxVoting && !o.noNms;
		cal.scoreRatio = o.scoreRatio && !o.noNms;
		if (o.regionFrames)
			cal.denseRegionPersistence = int(o.regionFrames);
		config.calibrated = cal;
	}
	return config;
}

bool resolveAutoResize(DetectorOptions &o, const Model &model, int width, int height,
		       const CameraModel *camera, std::string &note, std::string &error)
{
	note.clear();
	if (!o.resizeAuto)
		return true;
	if (!camera) {
		error = "--resize auto needs a calibration";
		return false;
	}
	AutoResizeSettings settings;
	settings.minPersonHeight = o.minHeight;
	settings.range = o.range;
	AutoResize chosen;
	const Status st = chooseResize(model.params, *camera, width, height, settings, chosen);
	if (!st.ok()) {
		error = std::string("--resize auto: ") + st.message() + " (give --resize R)";
		return false;
	}
	o.resize = chosen.resize;
	char text[200];
	std::snprintf(text, sizeof text,
		      "resize auto: %.3g (the smallest %.2f m person within %.0f m is %.0f px tall, "
		      "feet on row %.0f, %.1f m away; the model's person is %.0f px)",
		      chosen.resize, o.minHeight, o.range, chosen.smallestPersonPixels, chosen.footRow,
		      chosen.distance, double(model.params.modelDsH));
	note = text;
	return true;
}

bool createDetector(const Model &model, const DetectorOptions &options, int width, int height,
		    const CameraModel *camera, std::unique_ptr<Detector> &out, std::string &error,
		    std::string *note)
{
	// First: a calibration for other frames would otherwise show up as "no person fits".
	if (camera) {
		const Status fits = camera->checkFrameSize(width, height);
		if (!fits.ok()) {
			error = "--calib " + options.calibPath + ": " + fits.message();
			return false;
		}
	}
	DetectorOptions resolved = options;
	std::string resizeNote;
	if (!resolveAutoResize(resolved, model, width, height, camera, resizeNote, error))
		return false;
	if (note)
		*note = resizeNote;
	const Status st =
		Detector::create(model, makeDetectorConfig(resolved, width, height, camera), out);
	if (!st.ok()) {
		error = "cannot set up the detector for " + std::to_string(width) + "x" +
			std::to_string(height) + " frames: " + st.message();
		return false;
	}
	return true;
}

Detections filterByScore(const Detections &all, double minScore, std::vector<Detection> &kept)
{
	if (!(minScore > -INFINITY))
		return all;
	kept.clear();
	for (const Detection &d : all)
		if (d.score >= minScore)
			kept.push_back(d);
	Detections out;
	out.items = kept.data();
	out.count = static_cast<int>(kept.size());
	return out;
}

} // namespace calped::apps
