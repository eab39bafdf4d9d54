// SPDX-License-Identifier: BSD-2-Clause
// DetectorConfig::validate(): every setting in range, and no setting that the rest of the
// configuration would ignore.
#include <calped/calibration.h>
#include <calped/detector.h>

#include <algorithm>
#include <cmath>

#include <unistd.h>

#include "input/input_stage.h"

namespace calped {

namespace {

Status validateCalibrated(const DetectorConfig &c, const CalibratedSettings &s)
{
	if (!(s.minPersonHeight > 0 && s.maxPersonHeight >= s.minPersonHeight && s.maxPersonHeight < 10))
		return Status::error(ErrorCode::InvalidArgument, "calibrated.minPersonHeight %g and maxPersonHeight %g m are not a "
			       "range in (0, 10)",
			       s.minPersonHeight, s.maxPersonHeight);
	if (s.denseRegionPersistence < 1)
		return Status::error(ErrorCode::InvalidArgument, "calibrated.denseRegionPersistence %d must be >= 1",
			       s.denseRegionPersistence);
	if (s.maxDenseRegions < 1 || s.maxDenseRegions > (1 << 20))
		return Status::error(ErrorCode::InvalidArgument, "calibrated.maxDenseRegions %d is outside 1..1048576", s.maxDenseRegions);
	if (s.placedLevelReach < 1 || s.placedLevelReach > 16)
		return Status::error(ErrorCode::InvalidArgument, "calibrated.placedLevelReach %d is outside 1..16 levels",
			       s.placedLevelReach);
	// Placed levels are resampled from the frame: resizing it first would only add work.
	if (s.levels == PyramidLevels::Placed && c.resizeAt == ResizeAt::Frame && c.resize != 1.0)
		return Status::error(ErrorCode::InvalidArgument, "calibrated.levels Placed with resize %g needs resizeAt Pyramid "
			       "(or levels Toolbox)",
			       c.resize);
	if (!c.nms && (s.boxVoting || s.scoreRatio))
		return Status::error(ErrorCode::InvalidArgument, "nms off leaves nothing for calibrated.%s to work on: turn it off too",
			       s.boxVoting ? "boxVoting" : "scoreRatio");
	const CalibratedSettings defaults;
	if (!s.sparseDense && (s.denseRegionPersistence != defaults.denseRegionPersistence ||
			       s.maxDenseRegions != defaults.maxDenseRegions))
		return Status::error(ErrorCode::InvalidArgument, "calibrated.denseRegionPersistence and maxDenseRegions apply to "
			       "sparseDense only");
	return Status::success();
}

} // namespace

DetectionMethod DetectorConfig::resolvedMethod() const
{
	if (method != DetectionMethod::Auto)
		return method;
	return camera ? DetectionMethod::Calibrated : DetectionMethod::Generic;
}

Status DetectorConfig::validate() const
{
	if (maxWidth < 1 || maxHeight < 1 || maxWidth > 16384 || maxHeight > 16384)
		return Status::error(ErrorCode::InvalidArgument, "maximum frame size %dx%d is outside 1..16384", maxWidth, maxHeight);
	if (!(resize > 0.0 && resize <= 8.0))
		return Status::error(ErrorCode::InvalidArgument, "resize %g is outside (0, 8]", resize);
	if (resizeAt == ResizeAt::Pyramid && resize < 1.0)
		return Status::error(ErrorCode::InvalidArgument, "resize %g inside the pyramid: it only upscales (resizeAt Frame for "
			       "resizes below 1)",
			       resize);
	if (resizeAt == ResizeAt::Frame &&
	    (resizedSize(maxWidth, resize) < 1 || resizedSize(maxHeight, resize) < 1))
		return Status::error(ErrorCode::InvalidArgument, "resize %g leaves no pixels of %dx%d frames", resize, maxWidth, maxHeight);
	if (threads < 1 || threads > 64)
		return Status::error(ErrorCode::InvalidArgument,
				     "threads %d is outside 1..64 (the detector's worker threads, the calling one included)",
				     threads);
	if (maxCandidates < 1 || maxCandidates > (1 << 24))
		return Status::error(ErrorCode::InvalidArgument, "maxCandidates %d is outside 1..16777216", maxCandidates);
	// Scores are Q16 in 32 bits: a threshold must be representable.
	if (!std::isnan(cascadeThreshold) && !(std::fabs(cascadeThreshold) < 32768.0f))
		return Status::error(ErrorCode::InvalidArgument, "cascadeThreshold %g is outside (-32768, 32768)", double(cascadeThreshold));
	if (camera && !camera->valid())
		return Status::error(ErrorCode::InvalidArgument, "camera is not a valid calibration");
	// The calibration's pixels must be the frames'.
	if (camera) {
		const Status st = camera->checkFrameSize(maxWidth, maxHeight);
		if (!st.ok())
			return st;
	}
	const DetectionMethod m = resolvedMethod();
	if (m == DetectionMethod::Calibrated && !camera)
		return Status::error(ErrorCode::InvalidArgument, "the calibrated method needs a camera (DetectorConfig::camera)");
	if (m == DetectionMethod::Generic && calibrated)
		return Status::error(ErrorCode::InvalidArgument, "calibrated settings given, but the method is generic");
	if (m == DetectionMethod::Calibrated) {
		const Status st = validateCalibrated(*this, calibrated.value_or(CalibratedSettings()));
		if (!st.ok())
			return st;
	}
	if (staticRejection) {
		const StaticRejection &s = *staticRejection;
		if (s.difference < 1 || s.difference > 254)
			return Status::error(ErrorCode::InvalidArgument, "staticRejection.difference %d is outside 1..254 grey levels",
				       s.difference);
		if (!(s.minForeground >= 0.0f && s.minForeground <= 1.0f))
			return Status::error(ErrorCode::InvalidArgument, "staticRejection.minForeground %g is outside [0, 1]",
				       double(s.minForeground));
		// The first frame is its own background: it cannot tell anything apart.
		if (s.warmupFrames < 1)
			return Status::error(ErrorCode::InvalidArgument, "staticRejection.warmupFrames %d must be >= 1", s.warmupFrames);
	}
	return Status::success();
}

int recommendedThreads()
{
	const long cores = sysconf(_SC_NPROCESSORS_ONLN);
	return int(std::clamp(cores, 1L, 4L));
}

} // namespace calped
