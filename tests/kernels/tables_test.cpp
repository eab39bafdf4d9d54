// SPDX-License-Identifier: BSD-2-Clause
// The kernels' reciprocal and square-root tables hold what the toolbox's SSE code got from
// rcpps / rsqrtps on the Intel CPU that computed the reference (docs/channels.md), not
// exact values and not another maker's: its orientation channels depend on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "kernels.h"

using namespace calped::kernels;

namespace {

// The expected values below are Intel's results for a few inputs, written as float bit
// patterns: 12 fraction bits, the function taken at the middle of the input's 11-bit
// (rcpps) or 10-bit (rsqrtps) mantissa cell. The AMD EPYC of the development machine gives
// rcpps(1.5) = 0x3F2AA800 and rsqrtps(1.0) = 0x3F7FF800 instead.
float fromBits(uint32_t b)
{
	float f;
	static_assert(sizeof f == sizeof b, "float is 32 bits");
	std::memcpy(&f, &b, sizeof f);
	return f;
}

} // namespace

TEST(KernelTables, ColourReciprocalIsIntelRcpps)
{
	LuvTables t;
	buildLuvTables(t);
	// rcp[m - 4096] = 2^28 * rcpps(m) for the 13-bit mantissa m; rcpps(2^12 x) = rcpps(x) / 2^12.
	EXPECT_EQ(t.rcp[0], uint32_t(std::ldexp(fromBits(0x3F7FF000), 16)));    // rcpps(1.0)
	EXPECT_EQ(t.rcp[2048], uint32_t(std::ldexp(fromBits(0x3F2AA000), 16))); // rcpps(1.5)
	// Intel's rcpps depends on 11 fraction bits only: neighbouring 12-bit cells agree.
	for (int i = 0; i < 4096; i += 2)
		ASSERT_EQ(t.rcp[i], t.rcp[i + 1]) << i;
}

// The AMD EPYC's rcpps (family 26, where the Caltech+ and LDCF references were computed),
// from lib/kernels/amd_rcp_table.inc: values read from that CPU.
TEST(KernelTables, ColourReciprocalAmdEpyc)
{
	LuvTables t;
	buildLuvTables(t, RcpRule::AmdEpyc);
	EXPECT_EQ(t.rcp[0], uint32_t(std::ldexp(fromBits(0x3F7FF000), 16)));    // rcpps(1.0)
	EXPECT_EQ(t.rcp[2048], uint32_t(std::ldexp(fromBits(0x3F2AA800), 16))); // rcpps(1.5)
	EXPECT_EQ(t.rcp[1], uint32_t(std::ldexp(0.99951171875, 16)));          // rcpps(1 + 2^-12)
	EXPECT_EQ(t.rcp[4095], uint32_t(std::ldexp(0.5, 16)));                  // rcpps(2 - 2^-12)
	// Within 1.5 units of the 12th fraction bit of 1 / x over every cell.
	for (int i = 0; i < 4096; i++) {
		const double exact = std::ldexp(1.0 / (4096 + i + 0.5), 28);
		ASSERT_LE(std::fabs(t.rcp[i] - exact), 1.5 * 8) << i;
	}
}

TEST(KernelTables, GradientTablesAreIntelRsqrtps)
{
	GradientTables t;
	buildGradientTables(t, 6, 5, 0.005);
	// rsqrtQ20[m] = 2^20 * rsqrtps(m), exactly.
	EXPECT_EQ(t.rsqrtQ20[1], uint32_t(std::ldexp(fromBits(0x3F7FF000), 20))); // rsqrtps(1.0)
	EXPECT_EQ(t.rsqrtQ20[2], uint32_t(std::ldexp(fromBits(0x3F34F800), 20))); // rsqrtps(2.0)
	EXPECT_EQ(t.rsqrtQ20[6], uint32_t(std::ldexp(fromBits(0x3ED10000), 20))); // rsqrtps(6.0)
	EXPECT_EQ(t.rsqrtQ20[8], uint32_t(std::ldexp(fromBits(0x3EB4F800), 20))); // rsqrtps(8.0)
	// The magnitude is rcpps(rsqrtps(m2)): rcpps(rsqrtps(4.0)) = rcpps(0x3EFFF000) = 2.0 * 1.00024.
	EXPECT_EQ(t.sqrtQ8[4], uint16_t(std::lround(std::ldexp(fromBits(0x40000800), 8))));
	// The normalisation's reciprocal follows rcpps too: 1296 * 2^16 * rcpps(m).
	EXPECT_EQ(t.normRcp[1024], uint32_t(std::lround(1296.0 * std::ldexp(fromBits(0x3F2AA000), 5))));
}

TEST(KernelTables, OrientationFromTheToolboxArccosTable)
{
	GradientTables t;
	buildGradientTables(t, 6, 5, 0.005);
	const int bin = 1 << kOrientQ; // one orientation bin, pi / 6
	EXPECT_EQ(t.fromCos[kCosSteps], 3 * bin);                         // acos(0) = pi/2
	EXPECT_EQ(t.fromCos[2 * kCosSteps], 0);                           // acos(1) = 0
	EXPECT_EQ(t.fromCos[0], 6 * bin - 1);                             // capped below pi
	EXPECT_EQ(t.fromCos[kCosSteps + 5000], 2 * bin);                  // acos(0.5) = pi/3
	// One step of the cosine near 1 is a large angle: acos(0.9999) = 0.81 degrees.
	EXPECT_EQ(t.fromCos[2 * kCosSteps - 1], std::lround(std::acos(0.9999) * 6 / M_PI * bin));
}
