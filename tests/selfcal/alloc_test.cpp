// SPDX-License-Identifier: BSD-2-Clause
// SelfCalibrator::add() is called per frame: it must not allocate (counted with the
// replaced operator new of tests/common/alloc_counter.cpp).
#include <gtest/gtest.h>

#include <calped/self_calibration.h>

#include "common/alloc_counter.h"

namespace calped {
namespace {

TEST(SelfCalibratorAlloc, AddAllocatesNothing)
{
	SelfCalibrationConfig config;
	config.maxObservations = 256;
	SelfCalibrator c(config);
	ASSERT_TRUE(c.status().ok());
	Detection frame[8];
	for (int i = 0; i < 8; i++) {
		frame[i].x = float(20 + 60 * i);
		frame[i].y = float(50 + 20 * i);
		frame[i].w = 30;
		frame[i].h = float(70 + 5 * i);
		frame[i].score = float(40 + 10 * i);
	}
	test::startCountingAllocations();
	for (uint64_t k = 0; k < 1000; k++) // wraps the ring many times
		c.add(frame, 8, 640, 480, k);
	const long allocations = test::stopCountingAllocations();
	EXPECT_EQ(allocations, 0);
	EXPECT_EQ(c.size(), 256);
	std::printf("1000 frames of 8 detections: %d kept, %ld allocations\n", c.size(), allocations);
}

} // namespace
} // namespace calped
