// SPDX-License-Identifier: BSD-2-Clause
// Static-scene rejection on synthetic frames: a grey background with a bright block that
// either stays put (static structure) or moves (a walker), and detections on the block.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "input/frame_input.h"
#include "suppress/static_scene.h"

namespace calped {
namespace {

constexpr int kW = 160, kH = 120;

// Mid-grey frame with a 20x40 block of grey `level` whose top-left corner is (x, y).
std::vector<uint8_t> frameWithBlock(int x, int y, uint8_t level)
{
	std::vector<uint8_t> rgb(size_t(kW) * kH * 3, 100);
	for (int r = y; r < y + 40; r++)
		for (int c = x; c < x + 20; c++)
			for (int k = 0; k < 3; k++)
				rgb[(size_t(r) * kW + c) * 3 + k] = level;
	return rgb;
}

Detection boxAt(float x, float y)
{
	Detection d;
	d.x = x;
	d.y = y;
	d.w = 20;
	d.h = 40;
	return d;
}

class StaticSceneTest : public ::testing::Test
{
protected:
	void SetUp() override
	{
		ASSERT_TRUE(input_.init(kW, kH, false).ok());
		settings_.warmupFrames = 5;
		ASSERT_TRUE(scene_.init(kW, kH, settings_).ok());
	}

	// One frame: observe, reject `box`, update. Returns whether the box survived.
	bool frame(const std::vector<uint8_t> &rgb, Detection box, int width = kW, int height = kH)
	{
		input_.begin(ImageView::rgb8(rgb.data(), width, height));
		scene_.observe(input_);
		const int kept = scene_.reject(&box, 1);
		scene_.update();
		return kept == 1;
	}

	FrameInput input_;
	StaticRejection settings_;
	StaticScene scene_;
};

TEST_F(StaticSceneTest, StaticStructureIsDroppedOnceTheBackgroundIsTrusted)
{
	const std::vector<uint8_t> scene = frameWithBlock(60, 40, 200);
	for (int k = 0; k < settings_.warmupFrames; k++)
		EXPECT_TRUE(frame(scene, boxAt(60, 40))) << "dropped during warm-up, frame " << k;
	ASSERT_TRUE(scene_.ready());
	EXPECT_FALSE(frame(scene, boxAt(60, 40)));
	EXPECT_FLOAT_EQ(scene_.foreground(boxAt(60, 40)), 0.0f);
}

TEST_F(StaticSceneTest, AWalkerIsKept)
{
	// The background is the empty square; then a block walks across it.
	const std::vector<uint8_t> empty(size_t(kW) * kH * 3, 100);
	for (int k = 0; k < settings_.warmupFrames; k++)
		frame(empty, boxAt(0, 0));
	for (int x = 0; x + 20 <= kW; x += 8) {
		EXPECT_TRUE(frame(frameWithBlock(x, 40, 200), boxAt(float(x), 40))) << "x " << x;
		EXPECT_GT(scene_.foreground(boxAt(float(x), 40)), 0.5f);
	}
	// A box on empty ground next to the walker is dropped.
	EXPECT_FALSE(frame(frameWithBlock(0, 40, 200), boxAt(120, 60)));
}

TEST_F(StaticSceneTest, ASomeoneStandingStillFadesAtOneGreyLevelPerFrame)
{
	const std::vector<uint8_t> empty(size_t(kW) * kH * 3, 100);
	for (int k = 0; k < settings_.warmupFrames; k++)
		frame(empty, boxAt(0, 0));
	// 40 grey levels above the ground: kept while the background is more than
	// `difference` (10) away, i.e. for 30 frames, then dropped.
	const std::vector<uint8_t> standing = frameWithBlock(60, 40, 140);
	int keptFrames = 0;
	while (keptFrames < 100 && frame(standing, boxAt(60, 40)))
		keptFrames++;
	EXPECT_EQ(keptFrames, 40 - settings_.difference);
}

TEST_F(StaticSceneTest, ANewFrameSizeStartsAgain)
{
	const std::vector<uint8_t> scene = frameWithBlock(60, 40, 200);
	for (int k = 0; k < settings_.warmupFrames; k++)
		frame(scene, boxAt(60, 40));
	EXPECT_FALSE(frame(scene, boxAt(60, 40)));
	// The same pixels read as a narrower frame: the background is new, warm-up again.
	EXPECT_TRUE(frame(scene, boxAt(60, 40), kW - 40, kH));
	EXPECT_FALSE(scene_.ready());
}

TEST(StaticSceneCells, GreyIsTheCellMeanOfRPlusTwoGPlusBOverFour)
{
	// Random colours on a frame whose sides are not multiples of 4 (the last partial
	// cells are left out): every cell against the formula, pixel by pixel.
	const int w = 37, h = 22;
	std::vector<uint8_t> rgb(size_t(w) * h * 3);
	uint32_t seed = 12345;
	for (auto &v : rgb) {
		seed = seed * 1664525u + 1013904223u;
		v = uint8_t(seed >> 24);
	}
	FrameInput input;
	ASSERT_TRUE(input.init(w, h, false).ok());
	StaticScene scene;
	StaticRejection settings;
	ASSERT_TRUE(scene.init(w, h, settings).ok());
	input.begin(ImageView::rgb8(rgb.data(), w, h));
	scene.observe(input);
	ASSERT_EQ(scene.cellsWide(), w / 4);
	ASSERT_EQ(scene.cellsHigh(), h / 4);
	for (int cy = 0; cy < h / 4; cy++)
		for (int cx = 0; cx < w / 4; cx++) {
			uint32_t sum = 0;
			for (int y = 4 * cy; y < 4 * cy + 4; y++)
				for (int x = 4 * cx; x < 4 * cx + 4; x++) {
					const uint8_t *p = &rgb[(size_t(y) * w + x) * 3];
					sum += p[0] + 2u * p[1] + p[2];
				}
			ASSERT_EQ(scene.cellGrey(cx, cy), sum / 64) << cx << "," << cy;
		}
}

TEST(StaticSceneCells, ForegroundCountsAreThoseOfTheCells)
{
	// Two random frames: the first is the background; the cells of the second that differ
	// from it, counted over random rectangles by the summed-area table, against a count
	// cell by cell.
	const int w = 93, h = 61, cw = w / 4, ch = h / 4;
	uint32_t seed = 777;
	auto randomFrame = [&]() {
		std::vector<uint8_t> rgb(size_t(w) * h * 3);
		for (auto &v : rgb) {
			seed = seed * 1664525u + 1013904223u;
			v = uint8_t(seed >> 24);
		}
		return rgb;
	};
	FrameInput input;
	ASSERT_TRUE(input.init(w, h, false).ok());
	StaticScene scene;
	StaticRejection settings;
	settings.difference = 20;
	ASSERT_TRUE(scene.init(w, h, settings).ok());
	const std::vector<uint8_t> first = randomFrame(), second = randomFrame();
	input.begin(ImageView::rgb8(first.data(), w, h));
	scene.observe(input);
	std::vector<int> background(size_t(cw) * ch);
	for (int cy = 0; cy < ch; cy++)
		for (int cx = 0; cx < cw; cx++)
			background[size_t(cy) * cw + cx] = scene.cellGrey(cx, cy);
	scene.update(); // the background is the first frame: nothing to move towards
	input.begin(ImageView::rgb8(second.data(), w, h));
	scene.observe(input);
	int anyDiffering = 0;
	for (int k = 0; k < 500; k++) {
		seed = seed * 1664525u + 1013904223u;
		StaticScene::CellRect r;
		r.x0 = int(seed >> 8) % cw;
		r.x1 = r.x0 + int(seed >> 20) % (cw - r.x0);
		seed = seed * 1664525u + 1013904223u;
		r.y0 = int(seed >> 8) % ch;
		r.y1 = r.y0 + int(seed >> 20) % (ch - r.y0);
		int expected = 0;
		for (int cy = r.y0; cy <= r.y1; cy++)
			for (int cx = r.x0; cx <= r.x1; cx++)
				expected += std::abs(scene.cellGrey(cx, cy) - background[size_t(cy) * cw + cx]) >
					    settings.difference;
		ASSERT_EQ(scene.foregroundCells(r), expected)
			<< r.x0 << ".." << r.x1 << " x " << r.y0 << ".." << r.y1;
		EXPECT_EQ(scene.moving(r), float(expected) / float(r.count()) >= settings.minForeground);
		anyDiffering += expected > 0 && expected < r.count();
	}
	EXPECT_GT(anyDiffering, 100); // rectangles with some cells differing and some not
}


} // namespace
} // namespace calped
