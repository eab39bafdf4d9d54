// SPDX-License-Identifier: BSD-2-Clause
// PyramidLevels::Placed: computed levels placed among the needed ones. Every
// needed level must be served from a computed level within the reach asked for, and from
// the toolbox's reach up the placement must never compute more pixels than the toolbox's
// octaves for the same bands.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include "pyramid/placement.h"

namespace calped {
namespace {

constexpr int kMargin = 8; // the INRIA model's channel margin (Pyramid::channelMargin)

ScaleList scalesOf(const ModelParams &p, int width, int height, double upscale)
{
	ScaleList s;
	EXPECT_TRUE(computeScales(p, height, width, s, upscale));
	return s;
}

void checkPlacement(const ScaleList &scales, const CellRange *bands, const int *source, int reach)
{
	for (int i = 0; i < scales.count; i++) {
		const int s = source[i];
		ASSERT_GE(s, 0) << "level " << i;
		ASSERT_LT(s, scales.count);
		EXPECT_EQ(source[s], s) << "level " << i << " comes from level " << s << ", not computed";
		const bool needed = !bands[i].clipped(scales.levels[i].height).empty();
		if (needed) {
			EXPECT_LE(std::abs(i - s), reach) << "level " << i << " from level " << s;
		}
	}
}

TEST(Placement, ToolboxReachIsHalfItsSpacing)
{
	ModelParams p;
	EXPECT_EQ(toolboxReach(p), 4); // INRIA: nApprox 7, computed levels 8 apart
	p.nApprox = 3;
	EXPECT_EQ(toolboxReach(p), 2);
}

TEST(Placement, PetsLikeBandsComputeFarFewerPixels)
{
	// The shape the calibrated mode gives at resize 2 on a camera looking down at a
	// square: the 16 largest levels are needed, each in a band that moves down the
	// image as the scale falls (nearer people are lower and larger), the rest not at all.
	ModelParams p;
	ScaleList scales = scalesOf(p, 768, 576, 2.0);
	ASSERT_GE(scales.count, 20);
	CellRange bands[kMaxLevels];
	for (int i = 0; i < 16; i++) {
		const int h = scales.levels[i].height;
		bands[i] = CellRange{ h / 24 + i, h * 2 / 5 + 3 * i }.clipped(h);
	}
	const double octaves = computedPixels(p, scales, bands, kMargin);
	int source[kMaxLevels];
	ASSERT_TRUE(choosePlacedLevels(p, scales, bands, kMargin, toolboxReach(p), 768, 576, source));
	checkPlacement(scales, bands, source, toolboxReach(p));
	applyPlacedLevels(scales, source);
	const double placed = computedPixels(p, scales, bands, kMargin);
	int computed = 0;
	for (int i = 0; i < scales.count; i++)
		computed += scales.levels[i].computed;
	std::printf("PETS-like bands: octaves %.2f M channel pixels, placed %.2f M (%d computed levels)\n",
		    octaves / 1e6, placed / 1e6, computed);
	EXPECT_LT(placed, 0.75 * octaves);
	EXPECT_LE(computed, 2);
	// A longer reach can only find cheaper placements.
	ScaleList wider = scalesOf(p, 768, 576, 2.0);
	ASSERT_TRUE(choosePlacedLevels(p, wider, bands, kMargin, 5, 768, 576, source));
	checkPlacement(wider, bands, source, 5);
	applyPlacedLevels(wider, source);
	const double placed5 = computedPixels(p, wider, bands, kMargin);
	std::printf("reach 5: %.2f M channel pixels\n", placed5 / 1e6);
	EXPECT_LE(placed5, placed + 1024.0 * 2);
	for (int i = 16; i < scales.count; i++)
		EXPECT_FALSE(scales.levels[i].computed) << "level " << i << " is needed by nobody";
}

TEST(Placement, NeverMoreThanTheOctavesForRandomBands)
{
	ModelParams p;
	const ScaleList base = scalesOf(p, 331, 247, 1.5);
	std::mt19937 rng(11);
	for (int trial = 0; trial < 200; trial++) {
		SCOPED_TRACE(trial);
		CellRange bands[kMaxLevels];
		for (int i = 0; i < base.count; i++) {
			const int h = base.levels[i].height;
			const int b = int(rng() % h), e = b + 1 + int(rng() % h);
			bands[i] = rng() % 3 == 0 ? CellRange() : CellRange{ b, e };
		}
		int source[kMaxLevels];
		// Any reach from the toolbox's up: the toolbox's placement is then one of those
		// searched.
		const int reach = toolboxReach(p) + int(rng() % 4);
		if (!choosePlacedLevels(p, base, bands, kMargin, reach, 331, 247, source)) {
			for (int i = 0; i < base.count; i++)
				ASSERT_TRUE(bands[i].clipped(base.levels[i].height).empty());
			continue;
		}
		checkPlacement(base, bands, source, reach);
		ScaleList placed = base;
		applyPlacedLevels(placed, source);
		// The toolbox's placement is one of those searched; each computed level also
		// counts 1024 pixels there, so fewer levels may win by that much.
		EXPECT_LE(computedPixels(p, placed, bands, kMargin),
			  computedPixels(p, base, bands, kMargin) + 1024.0 * base.count);
	}
}

TEST(Placement, ComputedLevelsCanBeResampledFromTheImage)
{
	// Only the smallest levels of a large frame are needed: the resampler shrinks by at
	// most kMaxTaps - 1 in one step, so those levels are served from a larger one.
	ModelParams p;
	const int width = 2000, height = 1500;
	const ScaleList scales = scalesOf(p, width, height, 1.0);
	CellRange bands[kMaxLevels];
	for (int i = scales.count - 3; i < scales.count; i++)
		bands[i] = CellRange{ 0, scales.levels[i].height };
	int source[kMaxLevels];
	ASSERT_TRUE(choosePlacedLevels(p, scales, bands, kMargin, 5, width, height, source));
	checkPlacement(scales, bands, source, 5);
	std::vector<kernels::ResampleTap> taps(size_t(width) + 8);
	bool smallestComputable = true;
	for (int i = 0; i < scales.count; i++) {
		const PyramidLevel &l = scales.levels[i];
		const bool ok = kernels::buildResampleTaps(width, 4 * l.width, 1.0, taps.data()) &&
				kernels::buildResampleTaps(height, 4 * l.height, 1.0, taps.data());
		if (i == scales.count - 1)
			smallestComputable = ok;
		if (source[i] == i) {
			EXPECT_TRUE(ok) << "computed level " << i << " (scale " << l.scale << ")";
		}
	}
	EXPECT_FALSE(smallestComputable); // the case under test
}

TEST(Placement, NothingNeededOrEveryLevelComputedKeepsTheToolbox)
{
	ModelParams p;
	const ScaleList scales = scalesOf(p, 320, 240, 1.0);
	CellRange none[kMaxLevels];
	int source[kMaxLevels];
	EXPECT_FALSE(choosePlacedLevels(p, scales, none, kMargin, 5, 320, 240, source));
	CellRange all[kMaxLevels];
	for (int i = 0; i < scales.count; i++)
		all[i] = CellRange{ 0, scales.levels[i].height };
	p.nApprox = 0;
	EXPECT_FALSE(choosePlacedLevels(p, scales, all, kMargin, 5, 320, 240, source));
	p.nApprox = 7;
	EXPECT_FALSE(choosePlacedLevels(p, scales, all, kMargin, 0, 320, 240, source)); // no reach
}

} // namespace
} // namespace calped
