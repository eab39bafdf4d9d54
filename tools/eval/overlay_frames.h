// SPDX-License-Identifier: BSD-2-Clause
// Sample images for people: ground truth in blue (ignore boxes grey) and the detections
// scoring at least a threshold in green.
#pragma once

#include <string>
#include <vector>

#include "image_io.h"
#include "boxes.h"

namespace calped::eval_tool {

ports::RgbImage renderEvaluationOverlay(const ports::RgbImage &frame,
					      const std::vector<GtBox> &truth,
					      const std::vector<ScoredBox> &detections,
					      double minScore);

// "2.0" for the resizes people type (one decimal), "1.25" when one decimal is not enough.
std::string resizeLabel(double resize);

// "generic_r2.0": the stem of every per-run output file.
std::string runStem(const std::string &method, double resize);

} // namespace calped::eval_tool
