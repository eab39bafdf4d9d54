// SPDX-License-Identifier: BSD-2-Clause
#include "frame_detector.h"

#include <cmath>
#include <cstdio>

namespace calped::apps {

bool FrameDetector::create(const Model &model, const DetectorOptions &options, int width,
			   int height, const CameraModel *camera, std::string &error, std::string *note)
{
	fixed_.reset();
	selfCalibrating_.reset();
	if (!options.calibAuto()) {
		fixedMethod_ = options.methodName();
		return createDetector(model, options, width, height, camera, fixed_, error, note);
	}
	SelfCalibratingConfig config;
	DetectorOptions generic = options;
	generic.calibPath.clear();
	generic.method = MethodChoice::Generic;
	DetectorConfig base = makeDetectorConfig(generic, width, height, nullptr);
	base.method = DetectionMethod::Auto;
	// The calibrated method's settings, once the camera is known, are the options' own.
	DetectorOptions calibrated = options;
	calibrated.method = MethodChoice::Calibrated;
	calibrated.resize = 1.0; // placed levels; the resize itself is chosen per estimate
	calibrated.resizeAt = ResizeChoice::Default;
	base.calibrated = makeDetectorConfig(calibrated, width, height, nullptr).calibrated;
	config.detector = base;
	const Status st = SelfCalibratingDetector::create(model, config, selfCalibrating_);
	if (!st.ok()) {
		error = "--calib auto: cannot set up the detector for " + std::to_string(width) + "x" +
			std::to_string(height) + " frames: " + st.message();
		return false;
	}
	if (note) {
		char text[200];
		std::snprintf(text, sizeof text,
			      "calib auto: the generic method (resize %.3g) runs until the camera is "
			      "estimated from the people it finds",
			      base.resize);
		*note = text;
	}
	return true;
}

Status FrameDetector::detect(const ImageView &image, Detections &out)
{
	return fixed_ ? fixed_->detect(image, out) : selfCalibrating_->detect(image, out);
}

const FrameStats &FrameDetector::lastStats() const
{
	return fixed_ ? fixed_->lastStats() : selfCalibrating_->lastStats();
}

const char *FrameDetector::methodName() const
{
	if (fixed_)
		return fixedMethod_;
	return selfCalibrating_->lastMethod() == DetectionMethod::Calibrated ? "calibrated" : "generic";
}

int FrameDetector::cameraEstimate() const
{
	return fixed_ ? -1 : selfCalibrating_->cameraEstimate();
}

std::string FrameDetector::estimateChange()
{
	if (!selfCalibrating_ || selfCalibrating_->cameraEstimate() == reportedEstimate_)
		return std::string();
	reportedEstimate_ = selfCalibrating_->cameraEstimate();
	char text[400];
	if (reportedEstimate_ == 0) {
		std::snprintf(text, sizeof text,
			      "calib auto: the people no longer fit the camera estimate (was the camera "
			      "moved?): back to the generic method, estimating again");
		return text;
	}
	const SelfCalibrationResult &r = selfCalibrating_->lastEstimate();
	const double deg = 180.0 / M_PI;
	std::snprintf(text, sizeof text,
		      "calib auto: camera estimate %d from %d people: focal %.0f +- %.0f px, tilt "
		      "%.1f +- %.1f deg, roll %.1f deg, height %.2f +- %.2f m, horizon row %.0f; the "
		      "calibrated method runs at resize %.3g",
		      reportedEstimate_, r.inliers, r.focal.value, r.focal.sd, r.tilt.value * deg,
		      r.tilt.sd * deg, r.roll.value * deg, r.height.value, r.height.sd, r.horizonRow,
		      selfCalibrating_->calibratedResize());
	return text;
}

} // namespace calped::apps
