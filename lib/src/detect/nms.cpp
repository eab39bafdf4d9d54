// SPDX-License-Identifier: BSD-2-Clause
#include "detect/nms.h"

#include <algorithm>

namespace calped {

int nmsGreedy(Detection *boxes, int n, float overlap, bool useUnion, int *order, Detection *tmp)
{
	// Sort by score, descending; the index breaks ties so the result is the stable order.
	for (int i = 0; i < n; i++)
		order[i] = i;
	std::sort(order, order + n, [boxes](int a, int b) {
		if (boxes[a].score != boxes[b].score)
			return boxes[a].score > boxes[b].score;
		return a < b;
	});
	for (int i = 0; i < n; i++)
		tmp[i] = boxes[order[i]];

	// order[] now marks kept boxes (1) or suppressed ones (0).
	for (int i = 0; i < n; i++)
		order[i] = 1;
	for (int i = 0; i < n; i++) {
		if (!order[i])
			continue;
		const Detection &a = tmp[i];
		const float aArea = a.w * a.h;
		for (int j = i + 1; j < n; j++) {
			if (!order[j])
				continue;
			const Detection &b = tmp[j];
			const float iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
			if (iw <= 0)
				continue;
			const float ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
			if (ih <= 0)
				continue;
			const float inter = iw * ih, bArea = b.w * b.h;
			const float denom = useUnion ? aArea + bArea - inter : std::min(aArea, bArea);
			if (inter / denom > overlap)
				order[j] = 0;
		}
	}
	int kept = 0;
	for (int i = 0; i < n; i++)
		if (order[i])
			boxes[kept++] = tmp[i];
	return kept;
}

int suppressByScoreRatio(Detection *boxes, int n, int *keep)
{
	for (int i = 0; i < n; i++)
		keep[i] = 1;
	for (int j = 1; j < n; j++) {
		const Detection &b = boxes[j];
		for (int i = 0; i < j && keep[j]; i++) {
			if (!keep[i])
				continue;
			const Detection &a = boxes[i];
			const float iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
			const float ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
			if (iw <= 0 || ih <= 0)
				continue;
			const float inter = iw * ih;
			const float iou = inter / (a.w * a.h + b.w * b.h - inter);
			// Scores may be negative (cascade threshold below 0): then any overlap counts.
			const float ratio = a.score > 0 ? b.score / a.score : 0.0f;
			if (iou > ratio)
				keep[j] = 0;
		}
	}
	int kept = 0;
	for (int i = 0; i < n; i++)
		if (keep[i])
			boxes[kept++] = boxes[i];
	return kept;
}

} // namespace calped
