// SPDX-License-Identifier: BSD-2-Clause
// The toolbox's Caltech+ model (AcfCaltech+Detector: shrink 2, softBin 1, no colour
// smoothing, depth-5 trees) against the toolbox on PETS: levels 1 (computed) and 2
// (approximated) of frame 1, and the detections at native size.
#include <gtest/gtest.h>

#include <cstdio>

#include "parity_util.h"
#include "test_data.h"

using namespace calped;

namespace {

const char *const kName = "AcfCaltech+Detector";

} // namespace

TEST(CaltechParity, Frame1Levels1And2WithinTolerance)
{
	test::ToolboxFrame1 f;
	const test::Frame1 got = test::toolboxPyramidFrame1(kName, f);
	if (got == test::Frame1::Absent)
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	ASSERT_EQ(got, test::Frame1::Ready);
	Pyramid &pyr = f.pyramid;
	const std::vector<float> &ref = f.reference;
	// pyr_frame1_levels1-2.txt: level 1 is 296 x 390 (computed), level 2 272 x 358.
	const LevelChannels l1 = pyr.prepare(0);
	ASSERT_EQ(l1.paddedHeight, 296);
	ASSERT_EQ(l1.paddedWidth, 390);
	ASSERT_TRUE(pyr.scales().levels[0].computed);
	// Orientation channels 0.08-0.45% of their mean away (1.0-2.2% with Intel's rcpps, the
	// reference being from an AMD EPYC; what remains is mostly calped's Q16 LUV rounding:
	// docs/parity.md). Held at 0.6%, within issue 2's 1%.
	const double orientMean = 0.006;
	const size_t n1 = test::expectLevelWithinTolerance(l1, kChannelCount, ref, 0, "Caltech+ level 1",
							   orientMean);
	const LevelChannels l2 = pyr.prepare(1);
	ASSERT_EQ(l2.paddedHeight, 272);
	ASSERT_EQ(l2.paddedWidth, 358);
	ASSERT_FALSE(pyr.scales().levels[1].computed);
	const size_t n2 = test::expectLevelWithinTolerance(l2, kChannelCount, ref, n1, "Caltech+ level 2",
							   orientMean);
	EXPECT_EQ(n1 + n2, ref.size());
}

// The toolbox's detections over frames 1-795 at native size; the first 50 here, as for
// INRIA (about 0.06 s a frame: 4096 depth-5 trees over 2x2 cells). Issue 20's target is 95%
// matched both ways: 96.7% of the toolbox's 212 boxes and 96.7% of calped's 211, median
// score difference 1.00%, with the reference CPU's rcpps (Intel's: 92.0% / 93.3%, 1.45%).
TEST(CaltechParity, DetectionsNativeFrames1To50)
{
	const std::string shared = test::sharedDir();
	const std::string blob = test::toolboxModelBlob(kName);
	if (shared.empty() || blob.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	test::expectDetectionParity(blob,
				    shared + "/reference/dollar-toolbox-pets/" + kName +
					    "/dets_native_frames1-795.csv",
				    50, 1.0, ResizeAt::Frame, 0.95, ToolboxCpu::AmdEpyc);
}
