// SPDX-License-Identifier: BSD-2-Clause
#include <calped/self_calibrating_detector.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

namespace calped {

SelfCalibratingDetector::SelfCalibratingDetector(const Model &model,
						 const SelfCalibratingConfig &config)
	: model_(model), config_(config), calibrator_(config.selfCalibration)
{
}

Status SelfCalibratingDetector::create(const Model &model, const SelfCalibratingConfig &config,
				       std::unique_ptr<SelfCalibratingDetector> &out)
{
	out.reset();
	const DetectorConfig &d = config.detector;
	if (d.camera || d.method != DetectionMethod::Auto)
		return Status::error(ErrorCode::InvalidArgument,
				     "self-calibration: the detector configuration must have no camera "
				     "and method Auto");
	if (config.estimateEvery < 1 || config.checkEvery < 1 || config.checkObservations < 1 ||
	    !(config.minCheckFit >= 0 && config.minCheckFit <= 1) ||
	    !(config.footRowQuantile >= 0 && config.footRowQuantile < 1))
		return Status::error(ErrorCode::InvalidArgument,
				     "self-calibration: estimateEvery %d, checkEvery %d, checkObservations "
				     "%d, minCheckFit %g",
				     config.estimateEvery, config.checkEvery, config.checkObservations,
				     config.minCheckFit);
	std::unique_ptr<SelfCalibratingDetector> s(new (std::nothrow)
							   SelfCalibratingDetector(model, config));
	if (!s)
		return Status::error(ErrorCode::OutOfMemory, "self-calibrating detector");
	if (!s->calibrator_.status().ok())
		return s->calibrator_.status();
	// The calibrated method's settings are checked now, not at the first estimate.
	DetectorConfig withCamera = d;
	CameraModel probe;
	if (makeSelfCalibratedCamera(1000, 0.3, 0, 5, d.maxWidth / 2.0, d.maxHeight / 2.0, probe).ok()) {
		withCamera.camera = &probe;
		withCamera.method = DetectionMethod::Calibrated;
		const Status st = withCamera.validate();
		if (!st.ok())
			return st;
	}
	DetectorConfig generic = d;
	generic.method = DetectionMethod::Generic;
	generic.calibrated.reset();
	const Status st = Detector::create(model, generic, s->generic_);
	if (!st.ok())
		return st;
	out = std::move(s);
	return Status::success();
}

const FrameStats &SelfCalibratingDetector::lastStats() const
{
	return lastMethod_ == DetectionMethod::Calibrated ? calibrated_->lastStats()
							   : generic_->lastStats();
}

double SelfCalibratingDetector::observedFootRow() const
{
	std::vector<float> rows(size_t(calibrator_.size()));
	for (int i = 0; i < calibrator_.size(); i++)
		rows[size_t(i)] = calibrator_.observation(i).footV;
	const size_t k = std::min(rows.size() - 1, size_t(config_.footRowQuantile * double(rows.size())));
	std::nth_element(rows.begin(), rows.begin() + long(k), rows.end());
	return rows[k];
}

bool SelfCalibratingDetector::chooseCalibratedResize(const CameraModel &camera, double &out) const
{
	const DetectorConfig &d = config_.detector;
	AutoResizeSettings resize = config_.autoResize;
	resize.minPersonHeight = d.calibrated ? d.calibrated->minPersonHeight
					      : CalibratedSettings().minPersonHeight;
	resize.range = __builtin_inf();
	resize.minFootRow = observedFootRow();
	resize.maxResize = std::clamp(d.resize, resize.minResize, resize.maxResize);
	AutoResize chosen;
	if (!chooseResize(model_.params, camera, d.maxWidth, d.maxHeight, resize, chosen).ok())
		return false;
	out = chosen.resize;
	return true;
}

bool SelfCalibratingDetector::createCalibrated(double resize)
{
	DetectorConfig c = config_.detector;
	c.camera = &camera_;
	c.method = DetectionMethod::Calibrated;
	c.resize = resize;
	c.resizeAt = ResizeAt::Pyramid;
	if (!Detector::create(model_, c, calibrated_).ok()) {
		calibrated_.reset();
		return false;
	}
	calibratedResize_ = resize;
	return true;
}

void SelfCalibratingDetector::tryEstimate()
{
	if (calibrator_.size() < config_.selfCalibration.minInliers)
		return;
	if (calibrator_.estimate(result_) != SelfCalibrationVerdict::Ok)
		return;
	double resize = 0;
	if (!chooseCalibratedResize(result_.camera, resize))
		return;
	camera_ = result_.camera;
	if (!createCalibrated(resize)) {
		camera_ = CameraModel();
		return;
	}
	++estimate_;
	framesCalibrated_ = 0;
	checkSeen_ = checkFit_ = 0;
}

void SelfCalibratingDetector::check(const Detections &generic)
{
	const SelfCalibrationConfig &s = config_.selfCalibration;
	const CalibratedSettings plan = calibrated_->config().calibrated.value_or(CalibratedSettings());
	const float w = float(config_.detector.maxWidth), h = float(config_.detector.maxHeight);
	for (const Detection &d : generic) {
		if (d.score < s.minScore || d.h < s.minBoxHeight || d.x < s.borderMargin ||
		    d.y < s.borderMargin || d.x + d.w > w - s.borderMargin ||
		    d.y + d.h > h - s.borderMargin)
			continue;
		const Eigen::Vector2d foot(d.x + d.w / 2, d.y + d.h), head(d.x + d.w / 2, d.y);
		const double height = camera_.boxWorldHeight(foot, head);
		++checkSeen_;
		checkFit_ += height >= plan.minPersonHeight && height <= plan.maxPersonHeight;
	}
	if (checkSeen_ < config_.checkObservations)
		return;
	if (checkFit_ < config_.minCheckFit * checkSeen_) {
		// The people no longer fit the camera: start again.
		calibrated_.reset();
		camera_ = CameraModel();
		calibrator_.reset();
		framesCollecting_ = 0;
		++changes_;
	} else {
		// The camera holds; people seen since may reach rows the first choice did not.
		double resize = 0;
		if (chooseCalibratedResize(camera_, resize) && resize > calibratedResize_ + 1e-9)
			pendingResize_ = resize;
	}
	checkSeen_ = checkFit_ = 0;
}

Status SelfCalibratingDetector::detect(const ImageView &image, Detections &out)
{
	const uint64_t frame = frameIndex_++;
	if (calibrated_ && pendingResize_ > 0) {
		// Before this frame's detect(): the last frame's detections lived in the old one.
		const double resize = pendingResize_;
		pendingResize_ = 0;
		const double previous = calibratedResize_;
		if (!createCalibrated(resize) && !createCalibrated(previous))
			camera_ = CameraModel(); // neither: collect again
	}
	if (calibrated_) {
		lastMethod_ = DetectionMethod::Calibrated;
		lastEstimate_ = estimate_;
		const Status st = calibrated_->detect(image, out);
		if (!st.ok())
			return st;
		// The check so far failing: look again on this frame rather than checkEvery later.
		const bool failing = checkSeen_ > 0 && checkFit_ < config_.minCheckFit * checkSeen_;
		if (++framesCalibrated_ % config_.checkEvery == 0 || failing) {
			Detections generic;
			const Status gs = generic_->detect(image, generic);
			if (!gs.ok())
				return gs;
			calibrator_.add(generic.items, size_t(generic.count), image.width, image.height, frame);
			check(generic);
			if (!calibrated_) {
				// Dropped: this frame's detections are the generic method's.
				lastMethod_ = DetectionMethod::Generic;
				lastEstimate_ = 0;
				out = generic;
			}
		}
		return Status::success();
	}
	lastMethod_ = DetectionMethod::Generic;
	lastEstimate_ = 0;
	const Status st = generic_->detect(image, out);
	if (!st.ok())
		return st;
	calibrator_.add(out.items, size_t(out.count), image.width, image.height, frame);
	if (++framesCollecting_ % config_.estimateEvery == 0)
		tryEstimate();
	return Status::success();
}

} // namespace calped
