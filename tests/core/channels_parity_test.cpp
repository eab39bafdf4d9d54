// SPDX-License-Identifier: BSD-2-Clause
// Channels of PETS frame 1 at native size against Dollár's toolbox (chnsCompute).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <cmath>
#include <cstdlib>

#include "channels/channel_computer.h"
#include "test_data.h"

using namespace calped;

TEST(ChannelsParity, Frame1NativeWithinTolerance)
{
	const std::string shared = test::sharedDir();
	const std::string frame = test::petsFrame(1);
	if (shared.empty() || frame.empty())
		GTEST_SKIP() << "needs ../shared and data/pets/frames (scripts/fetch-pets.sh)";
	test::RgbImage img;
	ASSERT_TRUE(test::loadRgb(frame, img));
	ASSERT_EQ(img.width, 768);
	ASSERT_EQ(img.height, 576);

	kernels::LuvTables luvTables;
	kernels::buildLuvTables(luvTables);
	const int w = img.width, h = img.height;
	std::vector<uint16_t> luv(size_t(3) * w * h);
	kernels::rgbToLuv_ref(luvTables, img.pixels.data(), 3 * w, w, h, luv.data(),
			      luv.data() + w * h, luv.data() + 2 * w * h, w);

	ModelParams params;
	ChannelComputer cc;
	cc.init(params, w, h, kernels::bestKernels());
	Plane<const uint16_t> in[3];
	for (int c = 0; c < 3; c++)
		in[c] = { luv.data() + size_t(c) * w * h, w, h, w };
	const int cw = w / 4, ch = h / 4;
	std::vector<uint16_t> chns(size_t(kChannelCount) * cw * ch);
	Plane<uint16_t> out[kChannelCount];
	for (int c = 0; c < kChannelCount; c++)
		out[c] = { chns.data() + size_t(c) * cw * ch, cw, ch, cw };
	cc.compute(in, w, h, out);

	const std::vector<float> ref =
		test::readFloats(shared + "/reference/dollar-toolbox-pets/chns_frame1_chw.bin");
	ASSERT_EQ(ref.size(), chns.size());
	for (int c = 0; c < kChannelCount; c++) {
		std::vector<float> ours(size_t(cw) * ch);
		for (size_t i = 0; i < ours.size(); i++)
			ours[i] = chns[size_t(c) * cw * ch + i] / 16384.0f;
		const test::DiffStats d = test::compare(ours.data(), ref.data() + size_t(c) * cw * ch, ours.size());
		std::printf("channel %d: mean |diff| %.6f (%.3f%% of mean %.4f), p99 |diff| %.6f (%.3f%% of max %.4f), max |diff| %.5f\n",
			    c, d.meanAbs, 100 * d.meanAbs / d.meanA, d.meanA, d.p99Abs,
			    100 * d.p99Abs / d.maxA, d.maxA, d.maxAbs);
		// Target (issue #2): mean |diff| <= 1% of the channel's mean, 99th percentile <= 5%
		// of its maximum. The orientation channels are the sensitive ones (0.1-0.5%): they
		// need the toolbox's own approximate reciprocals reproduced (docs/parity.md).
		EXPECT_LE(d.meanAbs, 0.01 * d.meanA) << "channel " << c;
		EXPECT_LE(d.p99Abs, 0.05 * d.maxA) << "channel " << c;
	}
}
