// SPDX-License-Identifier: BSD-2-Clause
// What the programs detect with: a calped::Detector, or with `--calib auto` a
// calped::SelfCalibratingDetector, behind one interface (the frame loops do not care).
#pragma once

#include <memory>
#include <string>

#include <calped/calped.h>

#include "detector_options.h"

namespace calped::apps {

class FrameDetector
{
public:
	// Detector::create (createDetector) or, with --calib auto, SelfCalibratingDetector::create;
	// `note` receives the start-up line (resize auto, or what --calib auto does first).
	bool create(const Model &model, const DetectorOptions &options, int width, int height,
		    const CameraModel *camera, std::string &error, std::string *note = nullptr);
	bool valid() const { return fixed_ || selfCalibrating_; }

	Status detect(const ImageView &image, Detections &out);
	const FrameStats &lastStats() const;
	// The method of the last frame: "generic" or "calibrated".
	const char *methodName() const;
	// -1 without --calib auto; else 0 while collecting, then the estimate's number.
	int cameraEstimate() const;
	// With --calib auto: the line to print when the estimate in use changed since the last
	// call (applied or dropped), else empty.
	std::string estimateChange();

private:
	std::unique_ptr<Detector> fixed_;
	std::unique_ptr<SelfCalibratingDetector> selfCalibrating_;
	const char *fixedMethod_ = "generic";
	int reportedEstimate_ = 0;
};

} // namespace calped::apps
