// SPDX-License-Identifier: BSD-2-Clause
#include "detect/dense_regions.h"

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
	// Three boxes wide and two boxes high, centred on the box.
	regions_[count_++] = { cx - 1.5f * box.w, cy - box.h, cx + 1.5f * box.w, cy + box.h, 0 };
	return true;
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
