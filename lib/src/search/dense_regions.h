// SPDX-License-Identifier: BSD-2-Clause
// The dense regions of the calibrated method (thesis 3.2.2 and 3.4): around a sparse
// detection, a region three boxes wide and two high in which every plausible window is
// evaluated; regions persist across frames while they hold detections.
#pragma once

#include <calped/detector.h>

#include <vector>

namespace calped {

struct DenseRegion {
	float x0, y0, x1, y1; // input-image pixels
	int misses;           // consecutive frames without a detection inside
};

class DenseRegions
{
public:
	// Room for `capacity` regions; a region goes after `persistence` frames in a row
	// without a detection inside (1: the thesis, every frame).
	void init(int capacity, int persistence);

	int count() const { return count_; }
	const DenseRegion &operator[](int i) const { return regions_[i]; }

	// Whether (x, y) lies in any region.
	bool contains(float x, float y) const;

	// A region around a detection box, unless the box's centre is in one already; it is
	// cut back where it would overlap an existing region, so regions never overlap and
	// each holds its detection's centre. Returns false (and counts it) when the capacity
	// is reached.
	bool addAround(const Detection &box);

	// 3.4: regions without a detection inside this frame age; old ones are removed.
	void update(const Detection *detections, int n);

	uint64_t dropped() const { return dropped_; }

private:
	// Shrink r along one axis to end where `other` begins, keeping (cx, cy) inside r.
	static void clipAgainst(DenseRegion &r, const DenseRegion &other, float cx, float cy);

	std::vector<DenseRegion> regions_;
	int count_ = 0;
	int persistence_ = 1;
	uint64_t dropped_ = 0;
};

} // namespace calped
