// SPDX-License-Identifier: BSD-2-Clause
#include "suppress/nms.h"

#include <algorithm>

namespace calped {

namespace {

// Area of the intersection of two boxes (0 when they do not overlap).
float intersection(const Detection &a, const Detection &b)
{
	const float iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
	const float ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
	return iw > 0 && ih > 0 ? iw * ih : 0.0f;
}

// Keeps the boxes marked in keep[], in order, at the front of out.
int compact(const Detection *boxes, const int *keep, int n, Detection *out)
{
	int kept = 0;
	for (int i = 0; i < n; i++)
		if (keep[i])
			out[kept++] = boxes[i];
	return kept;
}

} // namespace

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
			const float inter = intersection(a, b);
			if (inter <= 0)
				continue;
			const float bArea = b.w * b.h;
			const float denom = useUnion ? aArea + bArea - inter : std::min(aArea, bArea);
			if (inter / denom > overlap)
				order[j] = 0;
		}
	}
	return compact(tmp, order, n, boxes);
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
			const float inter = intersection(a, b);
			if (inter <= 0)
				continue;
			const float iou = inter / (a.w * a.h + b.w * b.h - inter);
			// Scores may be negative (cascade threshold below 0): then any overlap counts.
			const float ratio = a.score > 0 ? b.score / a.score : 0.0f;
			if (iou > ratio)
				keep[j] = 0;
		}
	}
	return compact(boxes, keep, n, boxes);
}

void voteBoxes(Detection *kept, int nKept, const Detection *candidates, int nCandidates,
	       float minIou)
{
	for (int i = 0; i < nKept; i++) {
		Detection &k = kept[i];
		double sum = 0, x = 0, y = 0, w = 0, h = 0;
		for (int j = 0; j < nCandidates; j++) {
			const Detection &c = candidates[j];
			if (c.score <= 0)
				continue;
			const float inter = intersection(k, c);
			if (inter <= 0 || inter / (k.w * k.h + c.w * c.h - inter) <= minIou)
				continue;
			const double s2 = double(c.score) * c.score, weight = s2 * s2;
			sum += weight;
			x += weight * c.x;
			y += weight * c.y;
			w += weight * c.w;
			h += weight * c.h;
		}
		if (sum <= 0)
			continue;
		k.x = float(x / sum);
		k.y = float(y / sum);
		k.w = float(w / sum);
		k.h = float(h / sum);
	}
}

} // namespace calped
