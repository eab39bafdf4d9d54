// SPDX-License-Identifier: BSD-2-Clause
// One frame's matching (docs/evaluation.md): detections in descending score take the
// best-overlapping ground-truth box still free at IoU >= 0.5; each box is found at most once.
#pragma once

#include <vector>

#include "boxes.h"

namespace calped::eval_tool {

// IoU a detection needs to find a ground-truth box (PASCAL, thesis eq. 4.1).
constexpr double kMatchIou = 0.5;

enum class Outcome : unsigned char {
	FalsePositive,
	TruePositive,
	Ignored, // matched no counted box but an ignore box: neither true nor false
};

struct FrameMatch {
	std::vector<Outcome> outcomes; // per detection, in the input order
	int truePositives = 0;
	int falsePositives = 0;
	int ignored = 0;
	int groundTruth = 0; // counted boxes (ignore boxes excluded)
	int foundAny = 0;    // counted boxes some detection overlaps at IoU > 0.5 (thesis TPR)
};

// Equal scores keep the input order (a stable sort), so results never depend on the
// sort implementation.
FrameMatch matchFrame(const std::vector<ScoredBox> &detections, const std::vector<GtBox> &truth);

} // namespace calped::eval_tool
