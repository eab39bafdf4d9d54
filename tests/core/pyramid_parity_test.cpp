// SPDX-License-Identifier: BSD-2-Clause
// The pyramid of PETS frame 1 against Dollár's toolbox (chnsPyramid): scale lists at
// native size and upscaled 2x, and every smoothed, padded level at native size.
#include <cmath>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "pyramid/pyramid.h"
#include "test_data.h"

using namespace calped;

namespace {

struct RefScale {
	double scale, scaleH, scaleW;
	int computed, source, hShrunk, wShrunk, hPadded, wPadded;
};

std::vector<RefScale> readScales(const std::string &path)
{
	std::vector<RefScale> out;
	std::ifstream f(path);
	std::string line;
	while (std::getline(f, line)) {
		if (line.empty() || line[0] == '#')
			continue;
		std::istringstream s(line);
		int index;
		RefScale r;
		s >> index >> r.scale >> r.scaleH >> r.scaleW >> r.computed >> r.source >>
			r.hShrunk >> r.wShrunk >> r.hPadded >> r.wPadded;
		out.push_back(r);
	}
	return out;
}

void expectScalesMatch(const std::string &file, int height, int width)
{
	const std::string shared = test::sharedDir();
	if (shared.empty())
		GTEST_SKIP() << "needs ../shared";
	const auto ref = readScales(shared + "/reference/dollar-toolbox-pets/" + file);
	ASSERT_FALSE(ref.empty());
	ModelParams p;
	ScaleList s;
	ASSERT_TRUE(computeScales(p, height, width, s));
	std::printf("%s: %d levels (toolbox %zu)\n", file.c_str(), s.count, ref.size());
	ASSERT_EQ(size_t(s.count), ref.size());
	for (int i = 0; i < s.count; i++) {
		const PyramidLevel &l = s.levels[i];
		EXPECT_NEAR(l.scale, ref[i].scale, 1e-12) << "level " << i + 1;
		EXPECT_NEAR(l.scaleH, ref[i].scaleH, 1e-12) << "level " << i + 1;
		EXPECT_NEAR(l.scaleW, ref[i].scaleW, 1e-12) << "level " << i + 1;
		EXPECT_EQ(l.computed ? 1 : 0, ref[i].computed) << "level " << i + 1;
		EXPECT_EQ(l.source + 1, ref[i].source) << "level " << i + 1;
		EXPECT_EQ(l.height, ref[i].hShrunk) << "level " << i + 1;
		EXPECT_EQ(l.width, ref[i].wShrunk) << "level " << i + 1;
		EXPECT_EQ(l.height + 2 * p.padH / p.shrink, ref[i].hPadded) << "level " << i + 1;
		EXPECT_EQ(l.width + 2 * p.padW / p.shrink, ref[i].wPadded) << "level " << i + 1;
	}
}

} // namespace

TEST(PyramidParity, ScalesNative) { expectScalesMatch("scales_frame1.txt", 576, 768); }
TEST(PyramidParity, ScalesUpscaled2x) { expectScalesMatch("scales_frame1_up2x.txt", 1152, 1536); }

TEST(PyramidParity, ScalesOctaveUp)
{
	const std::string shared = test::sharedDir();
	if (shared.empty())
		GTEST_SKIP() << "needs ../shared";
	const auto ref = readScales(shared + "/reference/dollar-toolbox-pets/scales_frame1_octup1.txt");
	ModelParams p;
	p.nOctUp = 1;
	ScaleList s;
	ASSERT_TRUE(computeScales(p, 576, 768, s));
	ASSERT_EQ(size_t(s.count), ref.size());
	for (int i = 0; i < s.count; i++) {
		EXPECT_NEAR(s.levels[i].scale, ref[i].scale, 1e-12) << "level " << i + 1;
		EXPECT_EQ(s.levels[i].source + 1, ref[i].source) << "level " << i + 1;
	}
}

// Resizing inside the pyramid gives the resized frame's levels: the same sizes, with
// scales relative to the frame itself (resize 2 is nOctUp + 1 exactly).
TEST(PyramidScales, UpscaleInsideEqualsResizedFrame)
{
	ModelParams p;
	for (double r : { 1.5, 2.0, 2.5 }) {
		const int w = 768, h = 576, w1 = int(std::lround(w * r)), h1 = int(std::lround(h * r));
		ScaleList inside, resized;
		ASSERT_TRUE(computeScales(p, h, w, inside, r));
		ASSERT_TRUE(computeScales(p, h1, w1, resized));
		ASSERT_EQ(inside.count, resized.count) << "resize " << r;
		for (int i = 0; i < inside.count; i++) {
			const PyramidLevel &a = inside.levels[i], &b = resized.levels[i];
			EXPECT_EQ(a.width, b.width) << "resize " << r << " level " << i;
			EXPECT_EQ(a.height, b.height) << "resize " << r << " level " << i;
			EXPECT_NEAR(a.scale, b.scale * r, 1e-9) << "resize " << r << " level " << i;
			EXPECT_EQ(a.computed, b.computed);
			EXPECT_EQ(a.source, b.source);
		}
	}
	ModelParams up = p;
	up.nOctUp = 1;
	ScaleList twice, octUp;
	ASSERT_TRUE(computeScales(p, 576, 768, twice, 2.0));
	ASSERT_TRUE(computeScales(up, 576, 768, octUp));
	ASSERT_EQ(twice.count, octUp.count);
	for (int i = 0; i < twice.count; i++)
		EXPECT_EQ(twice.levels[i].scale, octUp.levels[i].scale) << "level " << i;
}

TEST(PyramidParity, Frame1LevelsWithinTolerance)
{
	const std::string shared = test::sharedDir();
	const std::string frame = test::petsFrame(1);
	if (shared.empty() || frame.empty())
		GTEST_SKIP() << "needs ../shared and data/pets/frames (scripts/fetch-pets.sh)";
	test::RgbImage img;
	ASSERT_TRUE(test::loadRgb(frame, img));
	const std::vector<float> ref =
		test::readFloats(shared + "/reference/dollar-toolbox-pets/pyr_frame1.bin");
	ASSERT_FALSE(ref.empty());

	ModelParams p;
	Pyramid pyr;
	ASSERT_TRUE(pyr.init(p, img.width, img.height).ok());
	const Status st = pyr.compute(img.pixels.data(), 3 * img.width, img.width, img.height);
	ASSERT_TRUE(st.ok()) << st.message();
	ASSERT_EQ(pyr.scales().count, 21);

	size_t offset = 0;
	double worstMeanPct = 0, worstP99Pct = 0;
	for (int i = 0; i < pyr.scales().count; i++) {
		const LevelChannels lc = pyr.prepare(i);
		const int h = lc.paddedHeight, w = lc.paddedWidth;
		ASSERT_LE(offset + size_t(h) * w * kChannelCount, ref.size());
		for (int c = 0; c < kChannelCount; c++) {
			std::vector<float> ours(size_t(h) * w), theirs(size_t(h) * w);
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					ours[size_t(y) * w + x] =
						lc.data[c * lc.planeStride + y * lc.rowStride + x] / 16384.0f;
					// Matlab column-major [h w c].
					theirs[size_t(y) * w + x] = ref[offset + y + size_t(h) * x + size_t(h) * w * c];
				}
			const test::DiffStats d = test::compare(ours.data(), theirs.data(), ours.size());
			const double meanPct = 100 * d.meanAbs / d.meanA, p99Pct = 100 * d.p99Abs / d.maxA;
			worstMeanPct = std::max(worstMeanPct, meanPct);
			worstP99Pct = std::max(worstP99Pct, p99Pct);
			std::printf("level %2d %s channel %d: mean |diff| %.3f%% of mean, p99 %.3f%% of max\n",
				    i + 1, pyr.scales().levels[i].computed ? "computed" : "approx  ", c,
				    meanPct, p99Pct);
			EXPECT_LE(d.meanAbs, 0.01 * d.meanA) << "level " << i + 1 << " channel " << c;
			EXPECT_LE(d.p99Abs, 0.05 * d.maxA) << "level " << i + 1 << " channel " << c;
		}
		offset += size_t(h) * w * kChannelCount;
	}
	std::printf("worst over levels and channels: mean %.3f%%, p99 %.3f%%\n", worstMeanPct, worstP99Pct);
}
