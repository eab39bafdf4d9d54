// SPDX-License-Identifier: BSD-2-Clause
// Calibrated detection without a calibration file (`--calib auto`; docs/calibration.md,
// "Online"): the generic method runs while a SelfCalibrator collects the people it finds;
// once the camera estimate is confident the calibrated method takes over with that camera
// and a resize chosen from it (chooseResize). Every checkEvery frames the generic method
// also runs on the frame: when too few of its confident detections have a plausible world
// height under the estimate (the camera was bumped or moved), the estimate is dropped and
// collection starts again with the generic method.
#pragma once

#include <memory>

#include <calped/auto_resize.h>
#include <calped/detector.h>
#include <calped/model.h>
#include <calped/self_calibration.h>
#include <calped/status.h>

namespace calped {

struct SelfCalibratingConfig {
	// Frame size and the settings of both methods: the generic method runs with it as given
	// (its resize is the collecting phase's, 2 by default: the INRIA model then sees people
	// from 50 pixels up); the calibrated method with the estimated camera, the resize
	// chosen for it, and `calibrated` (defaults when empty). camera must be null and the
	// method Auto. Frames must be exactly maxWidth x maxHeight (one camera).
	DetectorConfig detector = [] {
		DetectorConfig c;
		c.resize = 2.0;
		return c;
	}();
	// The estimate is used once camera height's relative sd is under 8% (the offline default
	// is 5%): the calibrated method's plausible heights (1.4-2.2 m) absorb that error, and
	// the checks below catch a camera that is wrong.
	SelfCalibrationConfig selfCalibration = [] {
		SelfCalibrationConfig c;
		c.maxRelativeSd = 0.08;
		return c;
	}();
	// Collecting: frames between two estimates (>= 1).
	int estimateEvery = 25;
	// Calibrated: every checkEvery-th frame also runs the generic method (>= 1).
	int checkEvery = 25;
	// A check decides once this many confident generic detections were seen (>= 1), and
	// drops the camera when fewer than minCheckFit of them (0..1) have a world height in
	// the calibrated settings' plausible range. While the boxes seen so far fail that
	// test, every frame is a check frame until it decides (a sparse scene would otherwise
	// need checkObservations / (boxes per frame) check frames, hundreds of frames, to notice
	// a bumped camera).
	int checkObservations = 30;
	double minCheckFit = 0.5;
	// The calibrated method's resize (its minPersonHeight is the calibrated settings'). The
	// region of interest is where the people were seen: feet from the footRowQuantile-th
	// quantile of the observations' foot rows down (the estimated focal length is too
	// uncertain for a range in metres, which is therefore not applied), and the resize is at
	// most the collecting phase's (people smaller than that one shows were not seen). The
	// check frames keep collecting, and a check that keeps the camera chooses again: a
	// larger resize (people seen farther away) replaces the calibrated detector.
	AutoResizeSettings autoResize;
	double footRowQuantile = 0.01;
};

class SelfCalibratingDetector
{
public:
	// Creates the generic detector and the observation buffer; `model` must outlive the
	// detector (the calibrated detector is created from it when the camera is estimated).
	static Status create(const Model &model, const SelfCalibratingConfig &config,
			     std::unique_ptr<SelfCalibratingDetector> &out);

	// One frame: detections of the method that ran (valid until the next call). Collecting
	// frames allocate nothing; a frame that estimates the camera, or switches to the
	// calibrated method, allocates (the fit's scratch, the calibrated detector), at most
	// once every estimateEvery frames.
	Status detect(const ImageView &image, Detections &out);

	// The method of the last frame (Generic while collecting).
	DetectionMethod lastMethod() const { return lastMethod_; }
	// The camera estimate the last frame's method used: 0 for the generic method, else its
	// number (1, 2, ...: each applied estimate, after a camera change too, gets the next
	// number). The frame on which an estimate arrives ran the generic method: 0; the next
	// frame is the first with the new number.
	int cameraEstimate() const { return lastEstimate_; }
	// The camera in use (valid() false while collecting) and the resize it was given.
	const CameraModel &camera() const { return camera_; }
	double calibratedResize() const { return calibratedResize_; }
	// The last estimate's result (verdict and message), and how many times a check
	// dropped the camera.
	const SelfCalibrationResult &lastEstimate() const { return result_; }
	int cameraChanges() const { return changes_; }
	const FrameStats &lastStats() const;
	const SelfCalibrator &observations() const { return calibrator_; }

private:
	SelfCalibratingDetector(const Model &model, const SelfCalibratingConfig &config);
	void tryEstimate();
	void check(const Detections &generic);
	double observedFootRow() const;
	bool chooseCalibratedResize(const CameraModel &camera, double &out) const;
	bool createCalibrated(double resize);

	const Model &model_;
	SelfCalibratingConfig config_;
	SelfCalibrator calibrator_;
	std::unique_ptr<Detector> generic_, calibrated_;
	CameraModel camera_;
	SelfCalibrationResult result_;
	double calibratedResize_ = 0, pendingResize_ = 0;
	long framesCollecting_ = 0, framesCalibrated_ = 0;
	int checkSeen_ = 0, checkFit_ = 0;
	int estimate_ = 0, changes_ = 0;
	uint64_t frameIndex_ = 0;
	DetectionMethod lastMethod_ = DetectionMethod::Generic;
	int lastEstimate_ = 0; // the estimate lastMethod_ used (0: generic)
};

} // namespace calped
