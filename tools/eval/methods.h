// SPDX-License-Identifier: BSD-2-Clause
// The detection methods the harness compares. Adding one is one entry in the registry in
// methods.cpp: a name, whether it needs --calib, and a factory.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "detector_options.h"

namespace calped::eval_tool {

// What every method is set up with; a method ignores what it does not use.
struct MethodSetup {
	const Model *model = nullptr;
	// --calib, --resize-at, --levels and the run's resize; each method sets the method
	// and static rejection (apps::makeDetectorConfig makes the DetectorConfig).
	apps::DetectorOptions options;
	int maxWidth = 0, maxHeight = 0;
};

// A detector as the harness drives it: one frame in, detections and the detector's own
// counters (FrameStats) out.
class Method
{
public:
	virtual ~Method() = default;
	// Detections stay valid until the next call.
	virtual Status detect(const ImageView &image, Detections &out) = 0;
	virtual const FrameStats &lastStats() const = 0;
};

using MethodFactory = bool (*)(const MethodSetup &setup, std::unique_ptr<Method> &out,
			       std::string &error);

struct MethodEntry {
	const char *name;
	// Without --calib such a method is named and skipped, not an error, so one command line
	// serves sequences with and without a calibration.
	bool needsCalibration;
	MethodFactory create;
};

const std::vector<MethodEntry> &methodRegistry();
// Null for a name not in the registry.
const MethodEntry *findMethod(const std::string &name);
// "generic, calibrated" for messages.
std::string methodNames();

} // namespace calped::eval_tool
