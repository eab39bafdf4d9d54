// SPDX-License-Identifier: BSD-2-Clause
// Sequence metrics: TPR, FPPF, the score sweep and the log-average miss rate.
#include <cmath>

#include <gtest/gtest.h>

#include "metrics.h"

namespace calped::eval_tool {
namespace {

// Frame f has people at x = 0, 100, ..., 100 * (f - 1): 1 + 2 + 3 = 6 boxes in 3 frames.
GroundTruth staircase(long frames)
{
	GroundTruth gt;
	for (long f = 1; f <= frames; f++)
		for (long i = 0; i < f; i++)
			gt.add(f, { Box{ 100.0 * i, 0, 30, 80 }, false });
	return gt;
}

SequenceDetections exactly(const GroundTruth &gt, long frames)
{
	SequenceDetections d(static_cast<size_t>(frames));
	double score = 100;
	for (long f = 1; f <= frames; f++)
		for (const GtBox &b : gt.boxes(f))
			d[static_cast<size_t>(f - 1)].push_back({ b.box, score-- });
	return d;
}

TEST(MissRateReferences, NineLogSpacedPointsFromOneHundredthToOne)
{
	const std::vector<double> r = missRateReferences();
	ASSERT_EQ(r.size(), 9u);
	EXPECT_DOUBLE_EQ(r.front(), 0.01);
	EXPECT_DOUBLE_EQ(r.back(), 1.0);
	EXPECT_NEAR(r[4], 0.1, 1e-15);
	for (size_t i = 1; i < r.size(); i++)
		EXPECT_NEAR(std::log10(r[i]) - std::log10(r[i - 1]), 0.25, 1e-12);
}

TEST(Metrics, DetectorThatFindsEverything)
{
	const GroundTruth gt = staircase(3);
	const Evaluation e = evaluateSequence(gt, exactly(gt, 3), 3);
	EXPECT_EQ(e.groundTruth, 6);
	EXPECT_EQ(e.truePositives, 6);
	EXPECT_EQ(e.falsePositives, 0);
	EXPECT_DOUBLE_EQ(e.tpr, 1.0);
	EXPECT_DOUBLE_EQ(e.tprAny, 1.0);
	EXPECT_DOUBLE_EQ(e.fppf, 0.0);
	// Miss rate 0 everywhere, floored at 1e-10 as in Dollár's code.
	EXPECT_NEAR(e.logAverageMissRate, 1e-10, 1e-20);
	ASSERT_EQ(e.curve.size(), 7u); // origin + one point per score
	EXPECT_DOUBLE_EQ(e.curve.back().tpr, 1.0);
}

TEST(Metrics, DetectorThatFindsNothing)
{
	const GroundTruth gt = staircase(3);
	SequenceDetections d(3);
	d[0].push_back({ Box{ 500, 300, 30, 80 }, 2 });
	d[2].push_back({ Box{ 600, 300, 30, 80 }, 1 });
	const Evaluation e = evaluateSequence(gt, d, 3);
	EXPECT_DOUBLE_EQ(e.tpr, 0.0);
	EXPECT_DOUBLE_EQ(e.tprAny, 0.0);
	EXPECT_DOUBLE_EQ(e.fppf, 2.0 / 3.0);
	EXPECT_DOUBLE_EQ(e.logAverageMissRate, 1.0);
}

TEST(Metrics, NoDetectionsAtAll)
{
	const Evaluation e = evaluateSequence(staircase(2), SequenceDetections(), 2);
	EXPECT_EQ(e.detections, 0);
	EXPECT_DOUBLE_EQ(e.tpr, 0.0);
	EXPECT_DOUBLE_EQ(e.fppf, 0.0);
	EXPECT_DOUBLE_EQ(e.logAverageMissRate, 1.0);
	ASSERT_EQ(e.curve.size(), 1u);
}

TEST(Metrics, EmptyFramesCountInFalsePositivesPerFrame)
{
	GroundTruth gt;
	gt.add(1, { Box{ 0, 0, 30, 80 }, false });
	SequenceDetections d(1);
	d[0].push_back({ Box{ 300, 0, 30, 80 }, 1 });
	// Frames 2..10 hold neither people nor detections.
	const Evaluation e = evaluateSequence(gt, d, 10);
	EXPECT_EQ(e.frames, 10);
	EXPECT_DOUBLE_EQ(e.fppf, 0.1);
}

TEST(Metrics, OnlyTheFramesProcessedAreScored)
{
	const GroundTruth gt = staircase(3);
	const Evaluation e = evaluateSequence(gt, exactly(gt, 2), 2);
	EXPECT_EQ(e.groundTruth, 3); // frame 3's boxes are not counted
	EXPECT_DOUBLE_EQ(e.tpr, 1.0);
}

TEST(Metrics, WithoutGroundTruthRatesAreUndefined)
{
	SequenceDetections d(1);
	d[0].push_back({ Box{ 0, 0, 30, 80 }, 1 });
	const Evaluation e = evaluateSequence(GroundTruth(), d, 1);
	EXPECT_TRUE(std::isnan(e.tpr));
	EXPECT_TRUE(std::isnan(e.logAverageMissRate));
	EXPECT_DOUBLE_EQ(e.fppf, 1.0);
}

TEST(Metrics, IgnoredDetectionsLeaveTheSweep)
{
	GroundTruth gt;
	gt.add(1, { Box{ 0, 0, 30, 80 }, true });
	gt.add(1, { Box{ 200, 0, 30, 80 }, false });
	SequenceDetections d(1);
	d[0].push_back({ Box{ 0, 0, 30, 80 }, 9 });   // on the ignore box
	d[0].push_back({ Box{ 200, 0, 30, 80 }, 5 }); // found
	const Evaluation e = evaluateSequence(gt, d, 1);
	EXPECT_EQ(e.groundTruth, 1);
	EXPECT_EQ(e.ignoreBoxes, 1);
	EXPECT_EQ(e.ignoredDetections, 1);
	EXPECT_DOUBLE_EQ(e.fppf, 0.0);
	ASSERT_EQ(e.curve.size(), 2u);
	EXPECT_DOUBLE_EQ(e.curve[1].score, 5);
}

TEST(Metrics, EqualScoresMakeOneCurvePoint)
{
	GroundTruth gt;
	gt.add(1, { Box{ 0, 0, 30, 80 }, false });
	gt.add(2, { Box{ 0, 0, 30, 80 }, false });
	SequenceDetections d(2);
	d[0].push_back({ Box{ 0, 0, 30, 80 }, 4 });   // true positive
	d[1].push_back({ Box{ 500, 0, 30, 80 }, 4 }); // false positive, same score
	d[1].push_back({ Box{ 0, 0, 30, 80 }, 1 });
	const Evaluation e = evaluateSequence(gt, d, 2);
	// A threshold keeps both score-4 detections or neither: no point at (0 FPPF, TPR 0.5).
	ASSERT_EQ(e.curve.size(), 3u);
	EXPECT_DOUBLE_EQ(e.curve[1].score, 4);
	EXPECT_DOUBLE_EQ(e.curve[1].fppf, 0.5);
	EXPECT_DOUBLE_EQ(e.curve[1].tpr, 0.5);
	EXPECT_DOUBLE_EQ(e.curve[2].tpr, 1.0);
}

TEST(LogAverageMissRate, KnownCurve)
{
	const double inf = INFINITY;
	const std::vector<CurvePoint> curve = {
		{ inf, 0, 0 }, { 9, 0.005, 0.5 }, { 8, 0.05, 0.6 }, { 7, 0.5, 0.8 }, { 6, 2.0, 0.9 },
	};
	std::vector<double> miss;
	const double lamr = logAverageMissRate(curve, &miss);
	// References 0.01 0.018 0.032 | 0.056 0.1 0.18 0.32 | 0.56 1: step interpolation
	// takes the last point at or below each.
	const std::vector<double> expected = { 0.5, 0.5, 0.5, 0.4, 0.4, 0.4, 0.4, 0.2, 0.2 };
	ASSERT_EQ(miss.size(), expected.size());
	for (size_t i = 0; i < expected.size(); i++)
		EXPECT_NEAR(miss[i], expected[i], 1e-12) << "reference " << i;
	const double want = std::exp((3 * std::log(0.5) + 4 * std::log(0.4) + 2 * std::log(0.2)) / 9);
	EXPECT_NEAR(lamr, want, 1e-12);
}

TEST(LogAverageMissRate, CurveStartingAboveOneHundredthAndEndingBelowOne)
{
	// Ten frames: the best detection is a false positive (FPPF 0.1 at once), and the sweep
	// ends at FPPF 0.3. References below 0.1 have miss rate 1; those above 0.3 keep the last.
	const double inf = INFINITY;
	const std::vector<CurvePoint> curve = { { inf, 0, 0 }, { 5, 0.1, 0 }, { 4, 0.1, 0.5 }, { 3, 0.3, 0.75 } };
	std::vector<double> miss;
	logAverageMissRate(curve, &miss);
	const std::vector<double> expected = { 1, 1, 1, 1, 0.5, 0.5, 0.25, 0.25, 0.25 };
	for (size_t i = 0; i < expected.size(); i++)
		EXPECT_NEAR(miss[i], expected[i], 1e-12) << "reference " << i;
}

TEST(LogAverageMissRate, ReferenceExactlyOnAPointIncludesIt)
{
	const double inf = INFINITY;
	const std::vector<CurvePoint> curve = { { inf, 0, 0 }, { 1, 0.01, 0.5 } };
	std::vector<double> miss;
	logAverageMissRate(curve, &miss);
	EXPECT_DOUBLE_EQ(miss[0], 0.5);
}

} // namespace
} // namespace calped::eval_tool
