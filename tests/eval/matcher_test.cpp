// SPDX-License-Identifier: BSD-2-Clause
// The per-frame matcher on hand-made cases (docs/evaluation.md, "Matching").
#include <gtest/gtest.h>

#include "matcher.h"

namespace calped::eval_tool {
namespace {

ScoredBox det(double x, double y, double w, double h, double score)
{
	return { Box{ x, y, w, h }, score };
}

GtBox gt(double x, double y, double w, double h, bool ignore = false)
{
	return { Box{ x, y, w, h }, ignore };
}

TEST(Iou, KnownOverlaps)
{
	EXPECT_DOUBLE_EQ(intersectionOverUnion({ 0, 0, 10, 10 }, { 0, 0, 10, 10 }), 1.0);
	EXPECT_DOUBLE_EQ(intersectionOverUnion({ 0, 0, 10, 10 }, { 10, 0, 10, 10 }), 0.0); // touching
	EXPECT_DOUBLE_EQ(intersectionOverUnion({ 0, 0, 10, 10 }, { 5, 0, 10, 10 }), 50.0 / 150.0);
	EXPECT_DOUBLE_EQ(intersectionOverUnion({ 0, 0, 10, 10 }, { 0, 0, 10, 20 }), 0.5);
	EXPECT_DOUBLE_EQ(intersectionOverUnion({ 0, 0, 0, 10 }, { 0, 0, 10, 10 }), 0.0); // empty box
}

TEST(Matcher, OneToOne)
{
	const FrameMatch m = matchFrame({ det(0, 0, 10, 20, 5), det(100, 0, 10, 20, 4) },
					{ gt(1, 1, 10, 20), gt(101, 0, 10, 20) });
	EXPECT_EQ(m.truePositives, 2);
	EXPECT_EQ(m.falsePositives, 0);
	EXPECT_EQ(m.groundTruth, 2);
	EXPECT_EQ(m.foundAny, 2);
	EXPECT_EQ(m.outcomes[0], Outcome::TruePositive);
	EXPECT_EQ(m.outcomes[1], Outcome::TruePositive);
}

TEST(Matcher, TwoDetectionsOnOneBoxMakeOneTrueAndOneFalsePositive)
{
	// The lower-scoring detection overlaps better, but the higher one is matched first.
	const FrameMatch m = matchFrame({ det(0, 0, 10, 20, 1.0), det(2, 0, 10, 20, 3.0) },
					{ gt(0, 0, 10, 20) });
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.falsePositives, 1);
	EXPECT_EQ(m.outcomes[1], Outcome::TruePositive);
	EXPECT_EQ(m.outcomes[0], Outcome::FalsePositive);
}

TEST(Matcher, EqualScoresKeepTheInputOrder)
{
	const FrameMatch a = matchFrame({ det(2, 0, 10, 20, 7), det(0, 0, 10, 20, 7) },
					{ gt(0, 0, 10, 20) });
	EXPECT_EQ(a.outcomes[0], Outcome::TruePositive);
	EXPECT_EQ(a.outcomes[1], Outcome::FalsePositive);
	const FrameMatch b = matchFrame({ det(0, 0, 10, 20, 7), det(2, 0, 10, 20, 7) },
					{ gt(0, 0, 10, 20) });
	EXPECT_EQ(b.outcomes[0], Outcome::TruePositive);
	EXPECT_EQ(b.outcomes[1], Outcome::FalsePositive);
}

TEST(Matcher, DetectionTakesTheBestOverlappingFreeBox)
{
	// Two people side by side. The first detection overlaps both (IoU 0.74 and 0.90) and
	// takes the better one, B; the second then overlaps A too little (0.48) to find it.
	const FrameMatch m = matchFrame({ det(1.5, 0, 10, 20, 2), det(3.5, 0, 10, 20, 1) },
					{ gt(0, 0, 10, 20), gt(2, 0, 10, 20) });
	EXPECT_EQ(m.outcomes[0], Outcome::TruePositive);
	EXPECT_EQ(m.outcomes[1], Outcome::FalsePositive);
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.foundAny, 2);
}

TEST(Matcher, ThresholdIsInclusiveForMatchingAndStrictForAnyOverlap)
{
	// IoU exactly 0.5: found by the matcher (>= 0.5), not by the thesis's "over 0.5".
	const FrameMatch m = matchFrame({ det(0, 0, 10, 10, 1) }, { gt(0, 0, 10, 20) });
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.foundAny, 0);
}

TEST(Matcher, AnyOverlapCountsBoxesTheGreedyMatchLeavesUnfound)
{
	// One detection between two boxes overlapping both at IoU > 0.5 finds only one of them
	// by the matcher, both by the thesis's criterion.
	const FrameMatch m = matchFrame({ det(1, 0, 10, 20, 1) }, { gt(0, 0, 10, 20), gt(2, 0, 10, 20) });
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.foundAny, 2);
}

TEST(Matcher, IgnoreBoxesAreNeitherTruthNorFalsePositives)
{
	const FrameMatch m = matchFrame(
		{ det(0, 0, 10, 20, 3), det(1, 0, 10, 20, 2), det(200, 0, 10, 20, 1), det(50, 0, 10, 20, 4) },
		{ gt(0, 0, 10, 20, true), gt(50, 0, 10, 20) });
	EXPECT_EQ(m.groundTruth, 1);
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.ignored, 2); // an ignore box absorbs any number of detections
	EXPECT_EQ(m.falsePositives, 1);
	EXPECT_EQ(m.outcomes[0], Outcome::Ignored);
	EXPECT_EQ(m.outcomes[1], Outcome::Ignored);
	EXPECT_EQ(m.outcomes[2], Outcome::FalsePositive);
	EXPECT_EQ(m.outcomes[3], Outcome::TruePositive);
}

TEST(Matcher, CountedBoxesArePreferredToIgnoreBoxes)
{
	// A detection overlapping a counted box and a better-fitting ignore box is a true positive.
	const FrameMatch m = matchFrame({ det(0, 0, 10, 20, 1) },
					{ gt(0, 0, 10, 20, true), gt(2, 0, 10, 20) });
	EXPECT_EQ(m.truePositives, 1);
	EXPECT_EQ(m.ignored, 0);
}

TEST(Matcher, EmptyFrames)
{
	const FrameMatch none = matchFrame({}, {});
	EXPECT_EQ(none.truePositives + none.falsePositives + none.groundTruth, 0);
	const FrameMatch onlyDets = matchFrame({ det(0, 0, 10, 20, 1) }, {});
	EXPECT_EQ(onlyDets.falsePositives, 1);
	const FrameMatch onlyTruth = matchFrame({}, { gt(0, 0, 10, 20) });
	EXPECT_EQ(onlyTruth.groundTruth, 1);
	EXPECT_EQ(onlyTruth.truePositives, 0);
}

} // namespace
} // namespace calped::eval_tool
