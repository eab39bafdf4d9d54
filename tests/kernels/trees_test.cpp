// SPDX-License-Identifier: BSD-2-Clause
// Boosted-tree evaluation of every kernel table against the scalar reference: random
// depth-2 models over random channels, grids and window lists, cascade thresholds from
// "nothing stops" to "everything stops at the first tree", window counts that do not fill
// the SIMD batches, unaligned channel buffers, and hit buffers smaller than the number of
// windows that pass. Scores, hit order and counts must be identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <random>
#include <string>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

// A level as the classifier lays it out: nChannels planes of height x width cells with
// strides wider than the rows; a model window is winRows x winCols cells.
struct Level {
	int width, height, nChannels;
	ptrdiff_t rowStride, planeStride;
	std::vector<uint16_t> buffer; // one spare sample in front, to start unaligned
	bool unaligned;
	const uint16_t *data() const { return buffer.data() + (unaligned ? 1 : 0); }
};

Level randomLevel(std::mt19937 &rng, int width, int height, int maxValue, bool unaligned)
{
	Level l;
	l.width = width;
	l.height = height;
	l.nChannels = 10;
	l.rowStride = width + 3;
	l.planeStride = l.rowStride * height + 5;
	l.unaligned = unaligned;
	l.buffer.resize(size_t(l.planeStride) * l.nChannels + 1);
	std::uniform_int_distribution<int> d(0, maxValue);
	for (auto &x : l.buffer)
		x = uint16_t(d(rng));
	return l;
}

// Leaves drift upwards a little, so scores wander: some windows stop at once, some after
// many trees, some never.
std::vector<Depth2Tree> randomTrees(std::mt19937 &rng, const Level &l, int nTrees, int winRows,
				    int winCols, int maxValue)
{
	std::uniform_int_distribution<int> z(0, l.nChannels - 1), r(0, winRows - 1), c(0, winCols - 1);
	std::uniform_int_distribution<int> thr(-2, maxValue + 2), leaf(-60000, 66000), kind(0, 19);
	std::vector<Depth2Tree> trees(nTrees);
	for (auto &t : trees) {
		for (int k = 0; k < 3; k++) {
			t.off[k] = uint32_t(z(rng) * l.planeStride + r(rng) * l.rowStride + c(rng));
			const int v = kind(rng);
			// Extremes now and then: thresholds no feature reaches, or every one does.
			t.thr[k] = v == 0 ? INT32_MIN : v == 1 ? INT32_MAX : v == 2 ? 65536 : thr(rng);
		}
		for (int k = 0; k < 4; k++)
			t.leaf[k] = leaf(rng);
	}
	return trees;
}

std::vector<const KernelTable *> tablesUnderTest()
{
	const KernelTable *all[8];
	const int n = availableKernelTables(all, 8);
	return std::vector<const KernelTable *>(all + 1, all + n);
}

void expectSameHits(const std::vector<WindowHit> &a, const std::vector<WindowHit> &b,
		    uint64_t written, const std::string &what)
{
	for (uint64_t i = 0; i < written; i++) {
		ASSERT_EQ(a[i].row, b[i].row) << what << " hit " << i;
		ASSERT_EQ(a[i].col, b[i].col) << what << " hit " << i;
		ASSERT_EQ(a[i].score, b[i].score) << what << " hit " << i;
	}
}

const int32_t kCascadeThresholds[] = { INT32_MIN, -200000, -65536, -1, 0, 40000, INT32_MAX };

} // namespace

TEST(TreeEquality, Depth2GridMatchesReference)
{
	std::mt19937 rng(18);
	const int winRows = 16, winCols = 8;
	struct Case {
		int width, height, step, nTrees, maxValue;
		bool unaligned;
	};
	const Case cases[] = { { 8, 16, 1, 64, 65535, false },  { 9, 17, 1, 33, 65535, true },
			       { 23, 19, 1, 200, 15, false },   { 30, 41, 2, 128, 65535, true },
			       { 47, 33, 1, 257, 300, true },   { 8, 30, 2, 1, 65535, false } };
	for (const Case &k : cases) {
		const Level l = randomLevel(rng, k.width, k.height, k.maxValue, k.unaligned);
		const auto trees = randomTrees(rng, l, k.nTrees, winRows, winCols, k.maxValue);
		const int rows = (k.height - winRows) / k.step + 1, cols = (k.width - winCols) / k.step + 1;
		const uint64_t n = uint64_t(rows) * cols;
		for (int32_t casc : kCascadeThresholds) {
			std::vector<WindowHit> want(n), got(n);
			const uint64_t passed = scanDepth2_ref(l.data(), l.rowStride, rows, cols, k.step,
							       trees.data(), k.nTrees, casc, want.data(), n);
			for (const KernelTable *t : tablesUnderTest()) {
				// Room for every hit, then for about half of them.
				for (uint64_t room : { n, passed / 2 }) {
					std::fill(got.begin(), got.end(), WindowHit{ -1, -1, -1 });
					const std::string what = std::string(t->name) + " " +
						std::to_string(k.width) + "x" + std::to_string(k.height) +
						" thr " + std::to_string(casc) + " room " + std::to_string(room);
					EXPECT_EQ(t->scanDepth2(l.data(), l.rowStride, rows, cols, k.step,
								trees.data(), k.nTrees, casc, got.data(), room),
						  passed) << what;
					expectSameHits(want, got, std::min(passed, room), what);
					if (room < n) {
						EXPECT_EQ(got[room].row, -1) << what << ": wrote past its room";
					}
				}
			}
		}
	}
}

TEST(TreeEquality, Depth2ListMatchesReference)
{
	std::mt19937 rng(5);
	const int winRows = 16, winCols = 8, step = 1;
	const Level l = randomLevel(rng, 40, 36, 65535, true);
	const int rows = 36 - winRows + 1, cols = 40 - winCols + 1;
	const auto trees = randomTrees(rng, l, 300, winRows, winCols, 65535);
	std::uniform_int_distribution<int> rr(0, rows - 1), cc(0, cols - 1);
	for (size_t count : { size_t(0), size_t(1), size_t(7), size_t(8), size_t(9), size_t(100),
			      size_t(613) }) {
		// Unordered, with repeats, as a list may come.
		std::vector<uint32_t> windows(count);
		for (auto &w : windows)
			w = uint32_t(rr(rng)) << 16 | uint32_t(cc(rng));
		for (int32_t casc : kCascadeThresholds) {
			std::vector<WindowHit> want(count + 1), got(count + 1);
			const uint64_t passed =
				scanDepth2List_ref(l.data(), l.rowStride, windows.data(), count, step,
						   trees.data(), 300, casc, want.data(), count);
			for (const KernelTable *t : tablesUnderTest()) {
				std::fill(got.begin(), got.end(), WindowHit{ -1, -1, -1 });
				const std::string what = std::string(t->name) + " count " +
					std::to_string(count) + " thr " + std::to_string(casc);
				EXPECT_EQ(t->scanDepth2List(l.data(), l.rowStride, windows.data(), count, step,
							    trees.data(), 300, casc, got.data(), count),
					  passed) << what;
				expectSameHits(want, got, passed, what);
				EXPECT_EQ(got[count].row, -1) << what;
			}
		}
	}
}

TEST(TreeEquality, CascadeSpreadsWindowsOverManyTrees)
{
	// The comparisons above mean something only if windows stop at many different trees
	// (a batch then holds lanes that stopped beside lanes still running): check that the
	// random models give that spread for a middle threshold.
	std::mt19937 rng(18);
	const Level l = randomLevel(rng, 47, 33, 300, true);
	const auto trees = randomTrees(rng, l, 257, 16, 8, 300);
	const int rows = 33 - 16 + 1, cols = 47 - 8 + 1;
	int minStop = 1 << 30, maxStop = 0, passedAll = 0;
	for (int r = 0; r < rows; r++)
		for (int c = 0; c < cols; c++) {
			const uint16_t *w = l.data() + r * l.rowStride + c;
			int32_t h = 0;
			int t = 0;
			for (; t < 257; t++) {
				const Depth2Tree &tr = trees[t];
				const int right = w[tr.off[0]] >= tr.thr[0];
				h += tr.leaf[2 * right + (w[tr.off[1 + right]] >= tr.thr[1 + right])];
				if (h <= -65536)
					break;
			}
			passedAll += t == 257;
			minStop = std::min(minStop, t);
			maxStop = std::max(maxStop, t);
		}
	EXPECT_LE(minStop, 2);
	EXPECT_GE(maxStop, 20);
	EXPECT_GT(passedAll, 0);
}
