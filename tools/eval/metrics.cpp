// SPDX-License-Identifier: BSD-2-Clause
#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "matcher.h"

namespace calped::eval_tool {

std::vector<double> missRateReferences()
{
	std::vector<double> refs;
	for (int i = 0; i <= 8; i++)
		refs.push_back(std::pow(10.0, -2.0 + 0.25 * i));
	return refs;
}

double logAverageMissRate(const std::vector<CurvePoint> &curve,
			  std::vector<double> *missAtReference)
{
	const std::vector<double> refs = missRateReferences();
	if (missAtReference)
		missAtReference->clear();
	double sumLog = 0;
	for (double r : refs) {
		// The curve is monotone in FPPF, so the last point within the budget has the
		// highest TPR reachable with at most r false positives per frame.
		double tpr = 0;
		for (const CurvePoint &p : curve) {
			if (p.fppf > r)
				break;
			tpr = p.tpr;
		}
		const double miss = 1.0 - tpr;
		if (missAtReference)
			missAtReference->push_back(miss);
		sumLog += std::log(std::max(miss, 1e-10));
	}
	return std::exp(sumLog / static_cast<double>(refs.size()));
}

Evaluation evaluateSequence(const GroundTruth &truth, const SequenceDetections &detections,
			    long frames)
{
	Evaluation e;
	e.frames = frames;
	struct Scored {
		double score;
		bool truePositive;
	};
	std::vector<Scored> sweep;
	for (long f = 1; f <= frames; f++) {
		static const std::vector<ScoredBox> kNone;
		const size_t k = static_cast<size_t>(f - 1);
		const std::vector<ScoredBox> &dets = k < detections.size() ? detections[k] : kNone;
		const std::vector<GtBox> &gt = truth.boxes(f);
		const FrameMatch m = matchFrame(dets, gt);
		e.groundTruth += m.groundTruth;
		e.ignoreBoxes += static_cast<long>(gt.size()) - m.groundTruth;
		e.detections += static_cast<long>(dets.size());
		e.truePositives += m.truePositives;
		e.falsePositives += m.falsePositives;
		e.ignoredDetections += m.ignored;
		e.foundAny += m.foundAny;
		// Greedy matching in score order makes every threshold's matching a prefix of
		// this one, so one pass labels the whole sweep. Ignored detections drop out.
		for (size_t i = 0; i < dets.size(); i++)
			if (m.outcomes[i] != Outcome::Ignored)
				sweep.push_back({ dets[i].score, m.outcomes[i] == Outcome::TruePositive });
	}

	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double gt = static_cast<double>(e.groundTruth);
	const double nf = static_cast<double>(std::max(frames, 1L));
	e.tpr = e.groundTruth ? e.truePositives / gt : nan;
	e.tprAny = e.groundTruth ? e.foundAny / gt : nan;
	e.fppf = frames > 0 ? e.falsePositives / nf : nan;

	std::stable_sort(sweep.begin(), sweep.end(),
			 [](const Scored &a, const Scored &b) { return a.score > b.score; });
	e.curve.push_back({ std::numeric_limits<double>::infinity(), 0.0, 0.0 });
	long tp = 0, fp = 0;
	for (size_t i = 0; i < sweep.size(); i++) {
		tp += sweep[i].truePositive;
		fp += !sweep[i].truePositive;
		// A threshold keeps all detections of equal score or none: one point per score.
		if (i + 1 < sweep.size() && sweep[i + 1].score == sweep[i].score)
			continue;
		e.curve.push_back({ sweep[i].score, fp / nf, e.groundTruth ? tp / gt : 0.0 });
	}
	if (e.groundTruth) {
		e.logAverageMissRate = logAverageMissRate(e.curve, &e.missAtReference);
	} else {
		e.logAverageMissRate = nan;
		e.missAtReference.assign(missRateReferences().size(), nan);
	}
	return e;
}

} // namespace calped::eval_tool
