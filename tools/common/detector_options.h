// SPDX-License-Identifier: BSD-2-Clause
// The detector flags shared by calped-detect, calped-eval and the live programs, and the
// one place a calped::DetectorConfig is filled from them (makeDetectorConfig): every
// assignment to a DetectorConfig field in the programs is there. Flags and defaults in
// docs/cli.md.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "args.h"

namespace calped::apps {

enum class MethodChoice { Default, Generic, Calibrated }; // Default: calibrated with --calib
enum class ResizeChoice { Default, Pyramid, Frame };         // Default: pyramid, frame when R < 1
enum class LevelsChoice { Default, Placed, Toolbox };         // Default: placed when it can be

struct DetectorOptions {
	std::string model;     // --model BLOB
	std::string calibPath; // --calib FILE
	MethodChoice method = MethodChoice::Default;
	double resize = 1.0;
	bool resizeGiven = false;
	bool resizeAuto = false; // --resize auto, the default with --calib (checkDetectorOptions)
	double range = 30.0;     // --range, metres: --resize auto's region of interest
	bool rangeGiven = false;
	ResizeChoice resizeAt = ResizeChoice::Default;
	LevelsChoice levels = LevelsChoice::Default;
	bool rejectStatic = false;
	double minHeight = 1.4, maxHeight = 2.2; // metres
	bool heightsGiven = false;
	bool noNms = false;
	bool noBoxVoting = false;
	bool scoreRatio = false;
	long regionFrames = 0; // 0: the library's default
	double minScore = -INFINITY; // --min-score: output filter, not a detector setting
	long threads = 0;            // --threads N; 0: the online cores, at most 4

	// The detector's threads: --threads, else the online cores (at most 4).
	int detectorThreads() const;

	// What the defaults resolve to (after checkDetectorOptions).
	bool calibrated() const;
	bool resizeInPyramid() const;
	bool placedLevels() const;
	const char *methodName() const { return calibrated() ? "calibrated" : "generic"; }
	// --calib auto: the camera estimated from the people the generic method finds.
	bool calibAuto() const { return calibPath == "auto"; }
};

// Which flags a program takes: the live programs and calped-detect take them all;
// calped-eval only those that make sense across its --methods and --resizes.
enum class DetectorFlags { All, Eval };

// The flags' table entries, for the program's own table.
std::vector<OptionSpec> detectorOptionTable(DetectorFlags which);

// Consumes one parsed option if it is a detector flag and returns true; `error` is then
// set when its value is bad (a usage error). False: not a detector flag.
bool takeDetectorOption(const ParsedOption &option, DetectorOptions &out, std::string &error);

// Cross-flag checks after parsing (usage errors): --method calibrated without --calib,
// --levels or --min/--max-height with the generic method, --resize-at pyramid below 1,
// placed levels with the frame resized first. `requireModel`: --model must be given.
bool checkDetectorOptions(DetectorOptions &options, bool requireModel, DetectorFlags which,
			  std::string &error);

// Model and calibration, read and checked (runtime errors).
struct DetectorInputs {
	Model model;
	CameraModel camera;
	bool hasCamera = false;
};
bool loadModelFile(const std::string &path, Model &model, std::string &error);
bool loadCalibrationFile(const std::string &path, CameraModel &camera, std::string &error);
bool loadDetectorInputs(const DetectorOptions &options, DetectorInputs &out, std::string &error);

// What the programs print when they run without a camera.
constexpr const char *kGenericHint =
	"no camera: the generic method runs; --calib FILE, or --calib auto (the camera estimated "
	"from the people found), runs the calibrated method, faster and with fewer false "
	"positives (docs/calibration.md)";

// THE DetectorConfig of the programs: frames up to width x height, `camera` (may be null
// for the generic method) must outlive Detector::create.
DetectorConfig makeDetectorConfig(const DetectorOptions &options, int width, int height,
				  const CameraModel *camera);

// --resize auto: sets options.resize from the camera (chooseResize, calped/auto_resize.h)
// and fills `note` with the line the programs print at start-up; nothing without it.
bool resolveAutoResize(DetectorOptions &options, const Model &model, int width, int height,
		       const CameraModel *camera, std::string &note, std::string &error);

// Detector::create with makeDetectorConfig (after resolveAutoResize), the error naming the
// frame size; `note`, when given, receives resolveAutoResize's line.
bool createDetector(const Model &model, const DetectorOptions &options, int width, int height,
		    const CameraModel *camera, std::unique_ptr<Detector> &out, std::string &error,
		    std::string *note = nullptr);

// --min-score: the detections at or above the threshold, in `kept` (reused: its capacity
// stays, so it allocates only while growing). Returns `all` itself without a threshold.
Detections filterByScore(const Detections &all, double minScore, std::vector<Detection> &kept);

} // namespace calped::apps
