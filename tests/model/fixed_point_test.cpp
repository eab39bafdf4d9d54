// SPDX-License-Identifier: BSD-2-Clause
// thresholdToFixed keeps every split decision of the float model; leaves round to nearest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <ios>
#include <limits>
#include <random>

#include <calped/model.h>

#include "model/fixed_convert.h"

namespace calped {
namespace {

constexpr int32_t kMin = std::numeric_limits<int32_t>::min();
constexpr int32_t kMax = std::numeric_limits<int32_t>::max();

// The toolbox's decision, evaluated exactly: channel value q / 2^14 against a float threshold.
bool floatGoesLeft(int64_t q, float t) { return static_cast<double>(q) / 16384.0 < t; }

void checkAround(float t)
{
	const int32_t fixed = thresholdToFixed(t);
	const int64_t centre = static_cast<int64_t>(std::floor(static_cast<double>(t) * 16384.0));
	for (int64_t q = centre - 3; q <= centre + 3; q++)
		ASSERT_EQ(q < fixed, floatGoesLeft(q, t))
			<< "t = " << std::hexfloat << t << std::defaultfloat << " (" << t << "), q = " << q
			<< ", fixed = " << fixed;
}

TEST(FixedPoint, ThresholdDecisionMatchesFloatForRandomThresholdsInZeroToTwo)
{
	std::mt19937 rng(2024);
	std::uniform_real_distribution<float> uniform(0.0f, 2.0f);
	for (int i = 0; i < 200000; i++)
		checkAround(uniform(rng));
}

TEST(FixedPoint, ThresholdDecisionMatchesFloatForEveryExponentAndSign)
{
	// Random bit patterns cover tiny, huge-but-representable and negative thresholds.
	std::mt19937 rng(77);
	int checked = 0;
	while (checked < 200000) {
		const uint32_t bits = static_cast<uint32_t>(rng());
		float t;
		std::memcpy(&t, &bits, 4);
		if (!std::isfinite(t) || std::fabs(t) > 100000.0f)
			continue; // beyond int32 after scaling; covered by the clamp test
		checkAround(t);
		checked++;
	}
}

TEST(FixedPoint, ThresholdsOnTheFixedGridMapToThemselves)
{
	for (int32_t k = -70000; k <= 70000; k += 7) {
		const float t = static_cast<float>(k) / 16384.0f; // exact: |k| < 2^24
		EXPECT_EQ(thresholdToFixed(t), k);
		// One float step above the grid point must move the threshold up by one.
		const float above = std::nextafter(t, 10.0f);
		EXPECT_EQ(thresholdToFixed(above), k + 1) << "t just above " << k;
		checkAround(std::nextafter(t, -10.0f));
	}
}

TEST(FixedPoint, NonFiniteAndOutOfRangeThresholdsClamp)
{
	EXPECT_EQ(thresholdToFixed(std::numeric_limits<double>::quiet_NaN()), kMin); // never left
	EXPECT_EQ(thresholdToFixed(-std::numeric_limits<double>::infinity()), kMin);
	EXPECT_EQ(thresholdToFixed(std::numeric_limits<double>::infinity()), kMax);
	EXPECT_EQ(thresholdToFixed(1e30), kMax);
	EXPECT_EQ(thresholdToFixed(-1e30), kMin);
	EXPECT_EQ(thresholdToFixed(-0.0), 0);
	EXPECT_EQ(thresholdToFixed(1e-30), 1);  // q = 0 is below a tiny positive threshold
	EXPECT_EQ(thresholdToFixed(-1e-30), 0); // but not below a tiny negative one
}

TEST(FixedPoint, LeafValuesRoundToNearestWithHalvesAwayFromZero)
{
	EXPECT_EQ(leafValueToFixed(0.0), 0);
	EXPECT_EQ(leafValueToFixed(1.0), 65536);
	EXPECT_EQ(leafValueToFixed(-0.25), -16384);
	EXPECT_EQ(leafValueToFixed(0.5 / 65536), 1);
	EXPECT_EQ(leafValueToFixed(-0.5 / 65536), -1);
	EXPECT_EQ(leafValueToFixed(0.49 / 65536), 0);
	// hs of the INRIA model's first root, 0.530308962f: 34754.33... -> 34754.
	EXPECT_EQ(leafValueToFixed(0.530308962f), 34754);
	EXPECT_EQ(leafValueToFixed(1e12), kMax);
	EXPECT_EQ(leafValueToFixed(-1e12), kMin);
	EXPECT_EQ(leafValueToFixed(std::numeric_limits<double>::quiet_NaN()), 0);
}

} // namespace
} // namespace calped
