// SPDX-License-Identifier: BSD-2-Clause
// LDCF's filter stage on demand (LdcfFilter::onDemand, what the classifier reads) against
// the whole level filtered at once (LdcfFilter::apply, the SIMD filter and resampler
// kernels): every cell equal, for levels of odd and even sizes, random and extreme
// channel values, and reads in any order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "classify/classifier.h"
#include "pyramid/ldcf_filter.h"
#include "synthetic.h"

using namespace calped;

namespace {

// A padded level of h x w cells, ten planes: random Q14 values, some saturated.
struct TestLevel {
	std::vector<uint16_t> data;
	LevelChannels view;
};

TestLevel randomLevel(uint32_t seed, int h, int w, bool extremes)
{
	TestLevel t;
	const ptrdiff_t rowStride = w + 3, planeStride = rowStride * (h + 1);
	t.data.resize(size_t(planeStride) * kChannelCount);
	std::mt19937 rng(seed);
	for (uint16_t &v : t.data) {
		const uint32_t r = rng();
		v = extremes ? (r % 3 == 0 ? 0 : r % 3 == 1 ? 65535 : uint16_t(r)) : uint16_t(r % 20000);
	}
	t.view.data = t.data.data();
	t.view.paddedHeight = h;
	t.view.paddedWidth = w;
	t.view.rowStride = rowStride;
	t.view.planeStride = planeStride;
	return t;
}

} // namespace

TEST(LdcfOnDemand, EveryCellEqualsTheWholeLevelFiltered)
{
	const Model model = test::randomLdcfModel(3, 16);
	const int planes = kChannelCount * model.params.nFilters;
	LdcfFilter dense, lazy;
	ASSERT_TRUE(dense.init(model, 40, 40).ok());
	ASSERT_TRUE(lazy.init(model, 40, 40).ok());
	size_t compared = 0;
	uint32_t seed = 0;
	for (int h : { 1, 2, 5, 16, 17, 40 })
		for (int w : { 1, 3, 6, 23, 40 })
			for (bool extremes : { false, true }) {
				const TestLevel level = randomLevel(seed++, h, w, extremes);
				const LevelChannels want = dense.apply(level.view);
				ASSERT_NE(want.data, nullptr);
				const LevelChannels got = lazy.onDemand(level.view);
				ASSERT_EQ(got.onDemand, &lazy);
				ASSERT_EQ(got.paddedHeight, want.paddedHeight);
				ASSERT_EQ(got.paddedWidth, want.paddedWidth);
				ASSERT_EQ(got.rowStride, want.rowStride);
				ASSERT_EQ(got.planeStride, want.planeStride);
				// Every cell, in a shuffled order, each read twice (computed, then remembered).
				std::vector<ptrdiff_t> cells;
				for (int p = 0; p < planes; p++)
					for (int y = 0; y < want.paddedHeight; y++)
						for (int x = 0; x < want.paddedWidth; x++)
							cells.push_back(p * want.planeStride + y * want.rowStride + x);
				std::shuffle(cells.begin(), cells.end(), std::mt19937(seed));
				for (int pass = 0; pass < 2; pass++)
					for (ptrdiff_t c : cells) {
						ASSERT_EQ(lazy.at(c), want.data[c])
							<< h << "x" << w << (extremes ? " extremes" : "") << ", cell " << c
							<< (pass ? " read again" : "");
						compared++;
					}
			}
	EXPECT_GT(compared, 100000u);
}

// A new level forgets the old one's cells, also after the generations wrap around: a cell
// read only by the first level and again by the level that reuses its generation number
// (the 256th) must be computed anew, not taken from the first.
TEST(LdcfOnDemand, ANewLevelIsComputedAnew)
{
	const Model model = test::randomLdcfModel(4, 16);
	LdcfFilter dense, lazy;
	ASSERT_TRUE(dense.init(model, 12, 12).ok());
	ASSERT_TRUE(lazy.init(model, 12, 12).ok());
	const ptrdiff_t everyLevel = 0, firstAndWrapped = 3 * 6 * 6 + 2 * 6 + 4; // plane 3, cell (2, 4)
	size_t wrappedChecked = 0;
	for (int k = 0; k < 600; k++) {
		const TestLevel level = randomLevel(1000 + uint32_t(k), 12, 12, false);
		const LevelChannels want = dense.apply(level.view);
		ASSERT_EQ(want.rowStride, 6);
		ASSERT_EQ(want.planeStride, 36);
		lazy.onDemand(level.view);
		ASSERT_EQ(lazy.at(everyLevel), want.data[everyLevel]) << "level " << k;
		if (k == 0 || k == 255 || k == 510) {
			ASSERT_EQ(lazy.at(firstAndWrapped), want.data[firstAndWrapped]) << "level " << k;
			wrappedChecked++;
		}
	}
	EXPECT_EQ(wrappedChecked, 3u);
}

// The classifier over a level on demand finds the windows and scores it finds over the
// level filtered at once, whether it scans every window or a list of them.
TEST(LdcfOnDemand, TheTreesScoreWhatTheyScoreOnTheWholeLevel)
{
	const Model model = test::randomLdcfModel(6, 64);
	const int h = 2 * model.params.modelDsPadH / (2 * model.params.shrink) + 9;
	const int w = 2 * model.params.modelDsPadW / (2 * model.params.shrink) + 7;
	LdcfFilter dense, lazy;
	ASSERT_TRUE(dense.init(model, h, w).ok());
	ASSERT_TRUE(lazy.init(model, h, w).ok());
	Classifier classifier;
	classifier.init(model, dense.rowStride(), dense.planeStride());
	classifier.setCascadeThreshold(-1000.0f); // every window a hit, with its score
	const TestLevel level = randomLevel(77, h, w, false);
	std::vector<kernels::WindowHit> want(4096), got(4096);
	uint64_t windows = 0;
	const uint64_t n = classifier.scan(dense.apply(level.view), want.data(), want.size(), &windows);
	ASSERT_GT(n, 8u);
	ASSERT_LE(n, want.size());
	uint64_t lazyWindows = 0;
	ASSERT_EQ(classifier.scan(lazy.onDemand(level.view), got.data(), got.size(), &lazyWindows), n);
	EXPECT_EQ(lazyWindows, windows);
	std::vector<uint32_t> list;
	for (uint64_t k = 0; k < n; k++) {
		EXPECT_EQ(got[k].row, want[k].row);
		EXPECT_EQ(got[k].col, want[k].col);
		EXPECT_EQ(got[k].score, want[k].score) << "window " << k;
		list.push_back(uint32_t(want[k].row) << 16 | uint32_t(want[k].col));
	}
	// A list, on a fresh level: every third window.
	std::vector<uint32_t> some;
	for (size_t k = 0; k < list.size(); k += 3)
		some.push_back(list[k]);
	const uint64_t m = classifier.scanList(lazy.onDemand(level.view), some.data(), some.size(), got.data(), got.size());
	ASSERT_EQ(m, some.size());
	for (uint64_t k = 0; k < m; k++)
		EXPECT_EQ(got[k].score, want[3 * k].score) << "listed window " << k;
}

// A weight beyond the loader's range (|w| <= 2^15, which ldcfCell's sums rely on) is refused.
TEST(LdcfOnDemand, AWeightBeyondQ15IsRefused)
{
	Model model = test::randomLdcfModel(8, 16);
	LdcfFilter filter;
	ASSERT_TRUE(filter.init(model, 12, 12).ok());
	model.filters[7] = (1 << 15) + 1;
	const Status st = filter.init(model, 12, 12);
	ASSERT_FALSE(st.ok());
	EXPECT_NE(std::string(st.message()).find("32769"), std::string::npos) << st.message();
}
