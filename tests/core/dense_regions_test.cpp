// SPDX-License-Identifier: BSD-2-Clause
// Dense regions (thesis 3.2.2, 3.4): three boxes wide and two high around a detection,
// never overlapping one another, removed after `persistence` frames without a detection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "search/dense_regions.h"

namespace calped {
namespace {

Detection box(float x, float y, float w, float h)
{
	Detection d;
	d.x = x;
	d.y = y;
	d.w = w;
	d.h = h;
	return d;
}

float overlapArea(const DenseRegion &a, const DenseRegion &b)
{
	const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
	const float h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
	return w > 0 && h > 0 ? w * h : 0;
}

bool holds(const DenseRegion &r, const Detection &d)
{
	const float cx = d.x + d.w / 2, cy = d.y + d.h / 2;
	return cx >= r.x0 && cx < r.x1 && cy >= r.y0 && cy < r.y1;
}

TEST(DenseRegions, AloneItIsThreeBoxesWideAndTwoHigh)
{
	DenseRegions regions;
	regions.init(4, 1);
	ASSERT_TRUE(regions.addAround(box(100, 50, 20, 40)));
	ASSERT_EQ(regions.count(), 1);
	const DenseRegion &r = regions[0];
	EXPECT_FLOAT_EQ(r.x0, 80);
	EXPECT_FLOAT_EQ(r.x1, 140);
	EXPECT_FLOAT_EQ(r.y0, 30);
	EXPECT_FLOAT_EQ(r.y1, 110);
}

TEST(DenseRegions, ANeighbourIsCutWhereTheFirstBegins)
{
	DenseRegions regions;
	regions.init(4, 1);
	ASSERT_TRUE(regions.addAround(box(100, 50, 20, 40))); // [80, 140] x [30, 110]
	// Centre (155, 70): outside the first; uncut it would span [125, 185] x [30, 110].
	ASSERT_TRUE(regions.addAround(box(145, 50, 20, 40)));
	ASSERT_EQ(regions.count(), 2);
	const DenseRegion &r = regions[1];
	EXPECT_FLOAT_EQ(r.x0, 140); // cut on the side facing the first region
	EXPECT_FLOAT_EQ(r.x1, 185);
	EXPECT_FLOAT_EQ(r.y0, 30);
	EXPECT_FLOAT_EQ(r.y1, 110);
	EXPECT_EQ(overlapArea(regions[0], regions[1]), 0);
	// A detection whose centre is in a region adds none.
	ASSERT_TRUE(regions.addAround(box(95, 45, 20, 40)));
	EXPECT_EQ(regions.count(), 2);
}

TEST(DenseRegions, ManyDetectionsNeverOverlapAndEachIsHeld)
{
	// A crowd: pseudo-random boxes of pedestrian shape, best first as the detector adds them.
	uint32_t state = 12345;
	auto next = [&state](float lo, float hi) {
		state = state * 1664525u + 1013904223u;
		return lo + (hi - lo) * float(state >> 8) / float(1u << 24);
	};
	DenseRegions regions;
	regions.init(256, 1);
	std::vector<Detection> added;
	for (int k = 0; k < 300; k++) {
		const float h = next(40, 160);
		const Detection d = box(next(0, 700), next(0, 500), 0.41f * h, h);
		const int before = regions.count();
		ASSERT_TRUE(regions.addAround(d));
		if (regions.count() > before) {
			EXPECT_TRUE(holds(regions[before], d)) << "detection " << k;
			added.push_back(d);
		}
	}
	ASSERT_GT(regions.count(), 20);
	for (int i = 0; i < regions.count(); i++) {
		EXPECT_LT(regions[i].x0, regions[i].x1);
		EXPECT_LT(regions[i].y0, regions[i].y1);
		for (int j = i + 1; j < regions.count(); j++)
			EXPECT_EQ(overlapArea(regions[i], regions[j]), 0) << i << " and " << j;
	}
}

TEST(DenseRegions, PersistenceAndCapacity)
{
	DenseRegions regions;
	regions.init(2, 2);
	ASSERT_TRUE(regions.addAround(box(100, 50, 20, 40)));
	ASSERT_TRUE(regions.addAround(box(400, 50, 20, 40)));
	EXPECT_FALSE(regions.addAround(box(700, 50, 20, 40))); // full: counted, not lost silently
	EXPECT_EQ(regions.dropped(), 1u);
	const Detection inFirst = box(100, 50, 20, 40);
	regions.update(&inFirst, 1); // the second misses once: kept (persistence 2)
	EXPECT_EQ(regions.count(), 2);
	regions.update(&inFirst, 1); // twice in a row: removed
	ASSERT_EQ(regions.count(), 1);
	EXPECT_TRUE(holds(regions[0], inFirst));
}

} // namespace
} // namespace calped
