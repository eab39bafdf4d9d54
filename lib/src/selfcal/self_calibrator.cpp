// SPDX-License-Identifier: BSD-2-Clause
// The observation buffer: a ring of fixed capacity filled from detections without
// allocating.
#include <calped/self_calibration.h>

#include <cmath>

#include "selfcal/fit.h"

namespace calped {

const char *selfCalibrationVerdictName(SelfCalibrationVerdict verdict)
{
	switch (verdict) {
	case SelfCalibrationVerdict::Ok: return "Ok";
	case SelfCalibrationVerdict::TooFewPeople: return "TooFewPeople";
	case SelfCalibrationVerdict::TooLittleDepthSpread: return "TooLittleDepthSpread";
	case SelfCalibrationVerdict::OnePlace: return "OnePlace";
	case SelfCalibrationVerdict::CameraMoving: return "CameraMoving";
	case SelfCalibrationVerdict::LookingStraightDown: return "LookingStraightDown";
	case SelfCalibrationVerdict::NotConverged: return "NotConverged";
	}
	return "?";
}

namespace {

Status checkConfig(const SelfCalibrationConfig &c)
{
	auto bad = [](const char *what) {
		return Status::error(ErrorCode::InvalidArgument, "SelfCalibrationConfig: %s", what);
	};
	if (c.maxObservations < 16 || c.maxObservations > (1 << 24))
		return bad("maxObservations must be in 16 .. 2^24");
	if (!std::isfinite(c.minScore))
		return bad("minScore must be finite");
	if (!(c.borderMargin >= 0) || !(c.minBoxHeight >= 1))
		return bad("borderMargin must be >= 0 and minBoxHeight >= 1");
	if (!(c.minAspect > 0) || !(c.maxAspect >= c.minAspect))
		return bad("aspect range must satisfy 0 < minAspect <= maxAspect");
	if (!(c.personHeight > 0.5 && c.personHeight < 3) || !(c.personHeightSd > 0 && c.personHeightSd < 1))
		return bad("personHeight must be in (0.5, 3) m and personHeightSd in (0, 1) m");
	if (!(c.pixelNoise > 0 && c.pixelNoise < 100))
		return bad("pixelNoise must be in (0, 100) px");
	if (c.minInliers < 8)
		return bad("minInliers must be >= 8");
	if (!(c.maxTilt > 0 && c.maxTilt < 1.5608))
		return bad("maxTilt must be in (0, 89.4 degrees)");
	if (!(c.minDepthSpread >= 0) || !(c.minFootSpread >= 0) || !(c.maxHeightShift > 0) ||
	    !(c.maxRelativeSd > 0))
		return bad("spread thresholds must be >= 0, maxHeightShift and maxRelativeSd > 0");
	return Status::success();
}

} // namespace

SelfCalibrator::SelfCalibrator(const SelfCalibrationConfig &config)
	: config_(config), status_(checkConfig(config))
{
	if (status_.ok())
		buffer_.resize(size_t(config.maxObservations));
}

void SelfCalibrator::reset()
{
	head_ = 0;
	count_ = 0;
}

const PersonObservation &SelfCalibrator::observation(int i) const
{
	const int capacity = int(buffer_.size());
	return buffer_[size_t((head_ - count_ + i + capacity) % capacity)];
}

void SelfCalibrator::addObservation(const PersonObservation &o, int imageWidth, int imageHeight)
{
	if (buffer_.empty() || imageWidth <= 0 || imageHeight <= 0)
		return;
	if (imageWidth != width_ || imageHeight != height_) {
		reset();
		width_ = imageWidth;
		height_ = imageHeight;
	}
	if (!std::isfinite(o.footU) || !std::isfinite(o.footV) || !std::isfinite(o.headV) ||
	    !(o.footV > o.headV))
		return;
	buffer_[size_t(head_)] = o;
	head_ = (head_ + 1) % int(buffer_.size());
	if (count_ < int(buffer_.size()))
		count_++;
}

void SelfCalibrator::add(const Detection *detections, size_t count, int imageWidth, int imageHeight,
			 uint64_t frameIndex)
{
	const SelfCalibrationConfig &c = config_;
	for (size_t i = 0; i < count; i++) {
		const Detection &d = detections[i];
		if (!(d.score >= c.minScore) || !(d.h >= c.minBoxHeight))
			continue;
		const float aspect = d.w / d.h;
		if (!(aspect >= c.minAspect && aspect <= c.maxAspect))
			continue;
		// Cut by the border: the foot or head is not where the box says.
		if (!(d.x >= c.borderMargin && d.y >= c.borderMargin &&
		      d.x + d.w <= float(imageWidth) - c.borderMargin &&
		      d.y + d.h <= float(imageHeight) - c.borderMargin))
			continue;
		// The calibrated method's foot and head (lib/src/detect/world_coordinates.cpp).
		PersonObservation o;
		o.footU = d.x + d.w / 2;
		o.footV = d.y + d.h;
		o.headV = d.y;
		o.frame = frameIndex;
		addObservation(o, imageWidth, imageHeight);
	}
}

SelfCalibrationVerdict SelfCalibrator::estimate(SelfCalibrationResult &out) const
{
	out = SelfCalibrationResult();
	if (!status_.ok()) {
		out.verdict = SelfCalibrationVerdict::NotConverged;
		out.message = status_.message();
		return out.verdict;
	}
	std::vector<PersonObservation> observations;
	observations.reserve(size_t(count_));
	for (int i = 0; i < count_; i++)
		observations.push_back(observation(i));
	return fitSelfCalibration(observations, width_, height_, config_, out);
}

} // namespace calped
