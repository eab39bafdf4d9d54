// SPDX-License-Identifier: BSD-2-Clause
// Self-calibration from walking people: collects the foot and head points of confident
// generic-mode detections and estimates the camera's focal length, tilt, roll and height
// above the ground (docs/calibration.md, "Self-calibration"). Principal point given (the
// image centre by default), square pixels, no lens distortion, yaw and ground position
// arbitrary (the camera stands above the world origin looking along +y).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/status.h>

namespace calped {

struct SelfCalibrationConfig {
	// Capacity of the observation buffer, fixed at construction (>= 16). When full, the
	// oldest observations are overwritten.
	int maxObservations = 4096;
	// Detections scoring below this are not collected.
	float minScore = 60.0f;
	// Boxes closer than this to the frame border (pixels) may be cut off: not collected.
	float borderMargin = 2.0f;
	// Box width / height outside [minAspect, maxAspect]: not an upright person.
	float minAspect = 0.25f, maxAspect = 0.6f;
	// Boxes lower than this (pixels) carry little height information.
	float minBoxHeight = 24.0f;
	// World height of a detection's box (its foot and head as the calibrated method uses
	// them, lib/src/detect: bottom and top centre), metres: mean and spread over people.
	// The camera height scales with the mean: a wrong mean biases it by the same factor.
	double personHeight = 1.7;
	double personHeightSd = 0.08;
	// Placement noise of a box's top and bottom rows, pixels (weights small boxes).
	double pixelNoise = 2.0;
	// Prior on the focal length, pixels (0: the image diagonal) and its sd in log units.
	// Axis-aligned boxes fix the focal length only through a small curvature of pixel
	// height against row (docs/calibration.md); the prior decides where they cannot.
	double focalPrior = 0;
	double focalPriorLogSd = 1.386; // ln 4
	// Principal point, pixels; negative: the image centre ((w - 1) / 2, (h - 1) / 2).
	double principalU = -1, principalV = -1;
	// Verdict thresholds.
	int minInliers = 30;                // TooFewPeople below this
	double minDepthSpread = 0.15;       // inlier foot rows: 10-90% range / image height
	double minFootSpread = 0.05;        // foot positions' spread / image diagonal
	double maxTilt = 1.31;              // radians (75 degrees): LookingStraightDown above
	double maxHeightShift = 0.1;        // first and last third predict pixel heights differing by more: CameraMoving
	double maxRelativeSd = 0.05;        // NotConverged when height's relative sd exceeds it
};

enum class SelfCalibrationVerdict {
	Ok,
	TooFewPeople,          // fewer confident whole boxes (inliers) than minInliers
	TooLittleDepthSpread,  // people all at about one distance: the horizon is not fixed
	OnePlace,              // every observation from one spot: one person standing still
	CameraMoving,          // the first and last third of the buffer (in time) disagree
	LookingStraightDown,   // tilt near 90 degrees: heights do not vary with the row
	NotConverged,          // the fit did not settle or its uncertainty is too large
};

const char *selfCalibrationVerdictName(SelfCalibrationVerdict verdict);

// An estimate with its standard deviation (from the inverse Hessian of the negative
// log-likelihood on the inliers, scaled by the residual variance when that exceeds 1). It
// does not include the bias of an assumed mean height that is wrong.
struct Estimate {
	double value = 0, sd = 0;
};

struct SelfCalibrationResult {
	SelfCalibrationVerdict verdict = SelfCalibrationVerdict::TooFewPeople;
	std::string message;        // human-readable: why, or a one-line summary when Ok
	Estimate focal;             // pixels
	Estimate tilt;              // radians below the horizontal (0 level, pi/2 straight down)
	Estimate roll;              // radians, positive turns the image clockwise
	Estimate height;            // camera height above the ground, metres
	double horizonRow = 0;      // at the principal point's column, pixels
	double principalU = 0, principalV = 0;
	int observations = 0;       // in the buffer when estimate() ran
	int inliers = 0;            // used by the final fit
	double residual = 0;        // RMS relative height residual of the inliers (sd of h / mean)
	double footRowSpread = 0;   // inliers' 10-90% foot row range / image height
	CameraModel camera;         // valid only when verdict == Ok
};

// The parameters of any camera as self-calibration sees them: focal (K(1,1) or, for a bare
// P, from its decomposition), tilt, roll, height of the centre, horizon row at column u.
// False when the camera is not valid.
struct CameraParameters {
	double focal = 0, tilt = 0, roll = 0, height = 0, horizonRow = 0;
};
bool cameraParameters(const CameraModel &camera, double u, CameraParameters &out);

// The camera (f, tilt, roll, height) with principal point (cu, cv), above the world origin
// looking along +y. InvalidArgument for f <= 0, height <= 0 or |tilt| >= pi/2.
Status makeSelfCalibratedCamera(double focal, double tilt, double roll, double height, double cu,
				double cv, CameraModel &out);

// OpenCV FileStorage YAML for `camera` (pinhole, no distortion, unit m), readable by
// loadOpenCvYaml(); `comment` lines go first as '#' comments.
Status formatOpenCvYaml(const CameraModel &camera, const std::string &comment, std::string &out);

// One head/foot pair in frame pixels.
struct PersonObservation {
	float footU = 0, footV = 0, headV = 0;
	uint64_t frame = 0;
};

class SelfCalibrator
{
public:
	// Allocates the buffer (config.maxObservations). Check status() before use.
	explicit SelfCalibrator(const SelfCalibrationConfig &config);
	// InvalidArgument naming the bad setting, else Ok.
	const Status &status() const { return status_; }
	const SelfCalibrationConfig &config() const { return config_; }

	// Keeps the confident, whole, upright boxes of one frame. Allocates nothing. A change of
	// image size clears the buffer (a new camera). frameIndex must not decrease.
	void add(const Detection *detections, size_t count, int imageWidth, int imageHeight,
		 uint64_t frameIndex);
	// Adds one observation directly (tests, tools with their own boxes). Allocates nothing.
	void addObservation(const PersonObservation &observation, int imageWidth, int imageHeight);

	// Fits the camera to the buffer. Allocates (temporary vectors; it runs rarely, not per
	// frame). The verdict says whether out.camera may be used.
	SelfCalibrationVerdict estimate(SelfCalibrationResult &out) const;

	// Forgets every observation (the camera was moved): collection starts again.
	void reset();
	int size() const { return count_; }
	int capacity() const { return int(buffer_.size()); }
	int imageWidth() const { return width_; }
	int imageHeight() const { return height_; }
	// Oldest first, i = 0 .. size() - 1.
	const PersonObservation &observation(int i) const;

private:
	SelfCalibrationConfig config_;
	Status status_;
	std::vector<PersonObservation> buffer_;
	int head_ = 0, count_ = 0;
	int width_ = 0, height_ = 0;
};

} // namespace calped
