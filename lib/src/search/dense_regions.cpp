// SPDX-License-Identifier: BSD-2-Clause
#include "search/dense_regions.h"

#include <algorithm>

namespace calped {

void DenseRegions::init(int capacity, int persistence)
{
	regions_.assign(capacity, DenseRegion{});
	count_ = 0;
	persistence_ = persistence < 1 ? 1 : persistence;
	dropped_ = 0;
}

bool DenseRegions::contains(float x, float y) const
{
	for (int i = 0; i < count_; i++) {
		const DenseRegion &r = regions_[i];
		if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1)
			return true;
	}
	return false;
}

bool DenseRegions::addAround(const Detection &box)
{
	const float cx = box.x + box.w / 2, cy = box.y + box.h / 2;
	if (contains(cx, cy))
		return true;
	if (count_ == int(regions_.size())) {
		dropped_++;
		return false;
	}
	// Three boxes wide and two boxes high, centred on the box, then cut back so that it
	// overlaps no existing region (the thesis restricts the regions' dimensions so).
	DenseRegion r = { cx - 1.5f * box.w, cy - box.h, cx + 1.5f * box.w, cy + box.h, 0 };
	for (int i = 0; i < count_; i++)
		clipAgainst(r, regions_[i], cx, cy);
	regions_[count_++] = r;
	return true;
}

void DenseRegions::clipAgainst(DenseRegion &r, const DenseRegion &other, float cx, float cy)
{
	if (r.x1 <= other.x0 || other.x1 <= r.x0 || r.y1 <= other.y0 || other.y1 <= r.y0)
		return;
	// The centre lies outside `other` (addAround checked), so at least one of the four
	// cuts keeps it; take the one that keeps the most area.
	const float w = r.x1 - r.x0, h = r.y1 - r.y0;
	const float kept[4] = { cx < other.x0 ? (other.x0 - r.x0) * h : -1,
				cx >= other.x1 ? (r.x1 - other.x1) * h : -1,
				cy < other.y0 ? (other.y0 - r.y0) * w : -1,
				cy >= other.y1 ? (r.y1 - other.y1) * w : -1 };
	const int cut = int(std::max_element(kept, kept + 4) - kept);
	if (cut == 0)
		r.x1 = other.x0;
	else if (cut == 1)
		r.x0 = other.x1;
	else if (cut == 2)
		r.y1 = other.y0;
	else
		r.y0 = other.y1;
}

void DenseRegions::update(const Detection *detections, int n)
{
	int kept = 0;
	for (int i = 0; i < count_; i++) {
		DenseRegion r = regions_[i];
		bool hit = false;
		for (int j = 0; j < n && !hit; j++) {
			const float cx = detections[j].x + detections[j].w / 2;
			const float cy = detections[j].y + detections[j].h / 2;
			hit = cx >= r.x0 && cx < r.x1 && cy >= r.y0 && cy < r.y1;
		}
		r.misses = hit ? 0 : r.misses + 1;
		if (r.misses < persistence_)
			regions_[kept++] = r;
	}
	count_ = kept;
}

} // namespace calped
