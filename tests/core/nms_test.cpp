// SPDX-License-Identifier: BSD-2-Clause
// Suppression and box voting on hand-made boxes whose outcome is worked out below.
#include <gtest/gtest.h>

#include <vector>

#include "suppress/nms.h"

namespace calped {
namespace {

Detection box(float x, float y, float w, float h, float score)
{
	Detection d;
	d.x = x;
	d.y = y;
	d.w = w;
	d.h = h;
	d.score = score;
	return d;
}

int runNms(std::vector<Detection> &boxes, float overlap, bool useUnion,
	   std::vector<Detection> *sorted = nullptr)
{
	std::vector<int> order(boxes.size());
	std::vector<Detection> tmp(boxes.size());
	const int kept = nmsGreedy(boxes.data(), int(boxes.size()), overlap, useUnion, order.data(),
				   tmp.data());
	if (sorted)
		*sorted = tmp;
	return kept;
}

TEST(Nms, OverlapOverTheSmallerBox)
{
	// A small box inside a big one overlaps it fully by the smaller area (1.0 > 0.65) but
	// only 0.25 by the union: the toolbox's 'maxg' (min) suppresses it, union keeps it.
	std::vector<Detection> boxes = { box(0, 0, 10, 20, 5), box(0, 0, 20, 40, 9) };
	EXPECT_EQ(runNms(boxes, 0.65f, false), 1);
	EXPECT_EQ(boxes[0].score, 9);
	boxes = { box(0, 0, 10, 20, 5), box(0, 0, 20, 40, 9) };
	EXPECT_EQ(runNms(boxes, 0.65f, true), 2);
	EXPECT_EQ(boxes[0].score, 9); // sorted by score
	EXPECT_EQ(boxes[1].score, 5);
}

TEST(Nms, GreedyChainKeepsTheThird)
{
	// a suppresses b; c overlaps b but not a, so c survives (b was removed first).
	std::vector<Detection> boxes = { box(0, 0, 10, 10, 3), box(3, 0, 10, 10, 2),
					 box(9, 0, 10, 10, 1) };
	// a-b: 7x10 = 70 / 100 = 0.7 > 0.65; a-c: 1x10 = 0.1; b-c: 0.4.
	ASSERT_EQ(runNms(boxes, 0.65f, false), 2);
	EXPECT_EQ(boxes[0].x, 0);
	EXPECT_EQ(boxes[1].x, 9);
}

TEST(Nms, EqualScoresKeepInputOrder)
{
	std::vector<Detection> boxes = { box(50, 0, 10, 10, 4), box(0, 0, 10, 10, 4) };
	ASSERT_EQ(runNms(boxes, 0.65f, false), 2);
	EXPECT_EQ(boxes[0].x, 50);
	EXPECT_EQ(boxes[1].x, 0);
}

TEST(ScoreRatio, RemovesWeakOverlappingBoxes)
{
	// IoU of a and b: 5x10 = 50 / 150 = 1/3. b/a = 0.2 < 1/3: removed. c/a = 0.5 > 1/3: kept.
	std::vector<Detection> boxes = { box(0, 0, 10, 10, 10), box(5, 0, 10, 10, 2) };
	std::vector<int> keep(2);
	EXPECT_EQ(suppressByScoreRatio(boxes.data(), 2, keep.data()), 1);
	boxes = { box(0, 0, 10, 10, 10), box(5, 0, 10, 10, 5) };
	EXPECT_EQ(suppressByScoreRatio(boxes.data(), 2, keep.data()), 2);
}

TEST(BoxVoting, WeightedMeanOfOverlappingCandidates)
{
	// Two candidates overlapping the kept box at IoU > 0.6 with scores 2 and 1: weights 16
	// and 1, so x = (16 * 0 + 1 * 1) / 17. A far box and a negative score do not vote.
	std::vector<Detection> all = { box(0, 0, 10, 20, 2), box(1, 0, 10, 20, 1),
				       box(100, 0, 10, 20, 3), box(0, 1, 10, 20, -4) };
	std::vector<Detection> kept = { all[0] };
	voteBoxes(kept.data(), 1, all.data(), int(all.size()), 0.6f);
	EXPECT_FLOAT_EQ(kept[0].x, 1.0f / 17);
	EXPECT_FLOAT_EQ(kept[0].y, 0);
	EXPECT_FLOAT_EQ(kept[0].w, 10);
	EXPECT_FLOAT_EQ(kept[0].h, 20);
	EXPECT_FLOAT_EQ(kept[0].score, 2); // scores are not changed
}

TEST(BoxVoting, AfterNmsUsesTheSuppressedWindows)
{
	// The best window sits 2 px left of two strong neighbours: voting moves it towards them.
	std::vector<Detection> boxes = { box(10, 0, 20, 50, 10), box(12, 0, 20, 50, 10),
					 box(8, 0, 20, 50, 11), box(300, 0, 20, 50, 7) };
	std::vector<Detection> sorted;
	const int kept = runNms(boxes, 0.65f, false, &sorted);
	ASSERT_EQ(kept, 2);
	ASSERT_EQ(boxes[0].x, 8);
	voteBoxes(boxes.data(), kept, sorted.data(), int(sorted.size()), 0.6f);
	const double w11 = 11.0 * 11 * 11 * 11, w10 = 10000.0;
	EXPECT_NEAR(boxes[0].x, (w11 * 8 + w10 * 10 + w10 * 12) / (w11 + 2 * w10), 1e-4);
	EXPECT_FLOAT_EQ(boxes[1].x, 300); // alone: unchanged
}

} // namespace
} // namespace calped
