// SPDX-License-Identifier: BSD-2-Clause
#include "matcher.h"

#include <algorithm>
#include <numeric>

namespace calped::eval_tool {

FrameMatch matchFrame(const std::vector<ScoredBox> &detections, const std::vector<GtBox> &truth)
{
	FrameMatch m;
	m.outcomes.assign(detections.size(), Outcome::FalsePositive);

	std::vector<size_t> order(detections.size());
	std::iota(order.begin(), order.end(), size_t(0));
	std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
		return detections[a].score > detections[b].score;
	});

	std::vector<bool> taken(truth.size(), false);
	for (size_t d : order) {
		const Box &det = detections[d].box;
		// Best free counted box; the first one wins a tie in IoU.
		long best = -1;
		double bestIou = 0;
		for (size_t g = 0; g < truth.size(); g++) {
			if (truth[g].ignore || taken[g])
				continue;
			const double iou = intersectionOverUnion(det, truth[g].box);
			if (iou >= kMatchIou && (best < 0 || iou > bestIou)) {
				best = static_cast<long>(g);
				bestIou = iou;
			}
		}
		if (best >= 0) {
			taken[static_cast<size_t>(best)] = true;
			m.outcomes[d] = Outcome::TruePositive;
			m.truePositives++;
			continue;
		}
		// Counted boxes are preferred; only a detection left over may fall on an ignore
		// box, and an ignore box may absorb any number of detections.
		for (const GtBox &g : truth) {
			if (g.ignore && intersectionOverUnion(det, g.box) >= kMatchIou) {
				m.outcomes[d] = Outcome::Ignored;
				break;
			}
		}
		if (m.outcomes[d] == Outcome::Ignored)
			m.ignored++;
		else
			m.falsePositives++;
	}

	for (const GtBox &g : truth) {
		if (g.ignore)
			continue;
		m.groundTruth++;
		for (const ScoredBox &d : detections) {
			if (intersectionOverUnion(d.box, g.box) > kMatchIou) {
				m.foundAny++;
				break;
			}
		}
	}
	return m;
}

} // namespace calped::eval_tool
