// SPDX-License-Identifier: BSD-2-Clause
// Sequence metrics (docs/evaluation.md): TPR and FPPF over all detections, the thesis's
// "any overlap" TPR, the TPR-vs-FPPF curve of the full score sweep and its log-average
// miss rate (Caltech protocol, Dollár's bbGt compRoc with reference FPPF 10^[-2:0.25:0]).
#pragma once

#include <vector>

#include "boxes.h"
#include "ground_truth.h"

namespace calped::eval_tool {

// One operating point: keep the detections scoring >= score.
struct CurvePoint {
	double score = 0;
	double fppf = 0;
	double tpr = 0;
};

// The nine reference FPPF of the log-average miss rate: 10^-2, 10^-1.75, ..., 10^0.
std::vector<double> missRateReferences();

struct Evaluation {
	long frames = 0;
	long groundTruth = 0;   // counted boxes in the frames scored
	long ignoreBoxes = 0;   // ignore boxes in the frames scored
	long detections = 0;
	long truePositives = 0;
	long falsePositives = 0;
	long ignoredDetections = 0;
	long foundAny = 0;
	double tpr = 0;      // NaN without ground truth
	double tprAny = 0;   // NaN without ground truth
	double fppf = 0;
	double logAverageMissRate = 0; // NaN without ground truth
	std::vector<double> missAtReference; // one per missRateReferences()
	// Starts at (score +inf, 0, 0); one point per distinct score, in descending score.
	std::vector<CurvePoint> curve;
};

// Scores frames 1..frames; `detections[k]` holds frame k + 1 (missing tail frames have
// none). Ground truth beyond `frames` is not counted.
Evaluation evaluateSequence(const GroundTruth &truth, const SequenceDetections &detections,
			    long frames);

// Log-average miss rate of a curve as above: at each reference FPPF r the miss rate is
// 1 - TPR of the last point with fppf <= r (step interpolation, the origin counting as a
// point); then exp(mean(log(max(miss, 1e-10)))). `missAtReference` may be null.
double logAverageMissRate(const std::vector<CurvePoint> &curve,
			  std::vector<double> *missAtReference);

} // namespace calped::eval_tool
