// SPDX-License-Identifier: BSD-2-Clause
// The calibrated mode computes each pyramid level only in the rows its windows read. Those
// rows (and the padding beside them) must equal the full pyramid's bit for bit: the bands
// are a saving, never an approximation.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "pixel_formats.h"
#include "pyramid/placement.h"
#include "pyramid/pyramid.h"
#include "synthetic.h"

namespace calped {
namespace {

// Padded rows of a level that a band of level rows makes valid: the band's rows, and the
// padding above or below only where the band reaches that edge of the level.
void checkLevelRows(const LevelChannels &full, const LevelChannels &part, const CellRange &band,
		    int levelHeight, int padH, int level)
{
	ASSERT_EQ(full.paddedHeight, part.paddedHeight);
	ASSERT_EQ(full.paddedWidth, part.paddedWidth);
	const int y0 = band.begin == 0 ? 0 : band.begin + padH;
	const int y1 = band.end == levelHeight ? full.paddedHeight : band.end + padH;
	int mismatches = 0;
	for (int c = 0; c < kChannelCount; c++)
		for (int y = y0; y < y1; y++) {
			const uint16_t *a = full.data + c * full.planeStride + y * full.rowStride;
			const uint16_t *b = part.data + c * part.planeStride + y * part.rowStride;
			if (std::memcmp(a, b, sizeof(uint16_t) * full.paddedWidth) != 0 && mismatches++ < 5)
				ADD_FAILURE() << "level " << level << " channel " << c << " padded row " << y
					      << " differs (band " << band.begin << ".." << band.end << ")";
		}
	EXPECT_EQ(mismatches, 0) << "level " << level;
}

// Random bands: empty, touching the top or bottom, one row, interior, beyond the level
// (the pyramid clips it), whole level.
void randomBands(std::mt19937 &rng, const ScaleList &scales, CellRange *bands)
{
	for (int i = 0; i < scales.count; i++) {
		const int h = scales.levels[i].height;
		const int kind = int(rng() % 6);
		int b = int(rng() % h), e = b + 1 + int(rng() % h);
		if (kind == 0)
			b = e = 0;
		else if (kind == 1)
			b = 0;
		else if (kind == 2)
			e = h;
		else if (kind == 3)
			e = b + 1;
		else if (kind == 4)
			b = -3, e = h + 5;
		bands[i] = CellRange{ b, e };
	}
}

void compareBands(const std::vector<uint8_t> &rgb, int width, int height, uint32_t seed,
		  PixelFormat format = PixelFormat::RGB8, bool placed = false)
{
	ModelParams p; // the INRIA model's options
	Pyramid full, banded;
	ASSERT_TRUE(full.init(p, width, height).ok());
	ASSERT_TRUE(banded.init(p, width, height).ok());
	// Camera formats are converted a strip of rows at a time, from the band's first row.
	const test::FormattedImage image = test::encodeImage(rgb.data(), width, height, format);
	FrameInput input;
	ASSERT_TRUE(input.init(width, height, false).ok());
	ASSERT_TRUE(checkImageLayout(image.view()).ok());
	ScaleList scales;
	ASSERT_TRUE(full.scalesFor(width, height, scales).ok());

	std::mt19937 rng(seed);
	CellRange bands[kMaxLevels];
	randomBands(rng, scales, bands);
	if (placed) {
		// Both pyramids compute the levels placed for these bands.
		int source[kMaxLevels];
		ASSERT_TRUE(choosePlacedLevels(p, scales, bands, full.channelMargin(), 5, width, height,
						 source));
		ASSERT_TRUE(full.placeLevels(source, scales.count).ok());
		ASSERT_TRUE(banded.placeLevels(source, scales.count).ok());
		applyPlacedLevels(scales, source);
	}
	input.begin(image.view());
	full.beginFrame();
	ASSERT_TRUE(full.compute(input, PyramidDemand::wholeFrame()).ok());
	for (int i = 0; i < scales.count; i++)
		ASSERT_EQ(full.scales().levels[i].source, scales.levels[i].source) << "level " << i;
	input.begin(image.view());
	// The bands as one demand of full-width rectangles.
	std::vector<int> levels;
	std::vector<LevelRect> rects;
	for (int i = 0; i < scales.count; i++)
		if (!bands[i].empty()) {
			levels.push_back(i);
			rects.push_back(LevelRect{ bands[i], CellRange{ 0, scales.levels[i].width } });
		}
	banded.beginFrame();
	ASSERT_TRUE(banded.compute(input, PyramidDemand::of(levels.data(), rects.data(), int(rects.size()))).ok());
	ASSERT_EQ(banded.scales().count, scales.count);
	EXPECT_LE(banded.computedCount, full.computedCount);

	for (int i = 0; i < scales.count; i++) {
		const CellRange band = bands[i].clipped(scales.levels[i].height);
		if (band.empty())
			continue;
		const LevelChannels part = banded.prepare(i); // each pyramid owns its level buffer
		const LevelChannels whole = full.prepare(i);
		checkLevelRows(whole, part, band, scales.levels[i].height, full.padCellsH(), i);
	}
}

TEST(PyramidBands, RowsEqualTheFullPyramid)
{
	const int width = 331, height = 247; // odd sizes: rounding of every level differs
	for (uint32_t seed = 1; seed <= 8; seed++) {
		SCOPED_TRACE(seed);
		compareBands(test::randomImage(seed, width, height), width, height, seed * 77);
	}
}

TEST(PyramidBands, RowsEqualTheFullPyramidUpscaled)
{
	// At resize 2 the first octave is the largest image: the calibrated mode's main case.
	const int width = 2 * 160, height = 2 * 124;
	compareBands(test::randomImage(9, width, height), width, height, 5);
}

TEST(PyramidBands, RowsEqualTheFullPyramidWithPlacedLevels)
{
	// PyramidLevels::Placed: computed levels among the needed ones, at scales
	// that are no octave of the image, some approximated by upsampling.
	const int width = 2 * 160 + 1, height = 2 * 124 - 1;
	for (uint32_t seed = 1; seed <= 6; seed++) {
		SCOPED_TRACE(seed);
		compareBands(test::randomImage(30 + seed, width, height), width, height, seed * 13,
			     PixelFormat::RGB8, true);
	}
}

// Placed levels built with nothing computed, then made preparable in rectangles
// (Pyramid::compute, twice, as the detector's two passes do): every rectangle equals
// the full pyramid's level there, padding included where it touches a side.
void compareRectangles(const std::vector<uint8_t> &rgb, int width, int height, uint32_t seed,
		       PixelFormat format)
{
	ModelParams p;
	Pyramid full, part;
	ASSERT_TRUE(full.init(p, width, height).ok());
	ASSERT_TRUE(part.init(p, width, height).ok());
	const test::FormattedImage image = test::encodeImage(rgb.data(), width, height, format);
	FrameInput input;
	ASSERT_TRUE(input.init(width, height, false).ok());
	ScaleList scales;
	ASSERT_TRUE(full.scalesFor(width, height, scales).ok());
	CellRange all[kMaxLevels];
	for (int i = 0; i < scales.count; i++)
		all[i] = CellRange{ 0, scales.levels[i].height };
	int source[kMaxLevels];
	ASSERT_TRUE(choosePlacedLevels(p, scales, all, full.channelMargin(), 5, width, height, source));
	ASSERT_TRUE(full.placeLevels(source, scales.count).ok());
	ASSERT_TRUE(part.placeLevels(source, scales.count).ok());
	ASSERT_TRUE(part.rectsComputable(width, height));
	input.begin(image.view());
	full.beginFrame();
	ASSERT_TRUE(full.compute(input, PyramidDemand::wholeFrame()).ok());
	input.begin(image.view());
	part.beginFrame();
	std::mt19937 rng(seed);
	for (int pass = 0; pass < 2; pass++) {
		// A few small rectangles on random levels, most inside (so their edges are not
		// the level's), some touching sides or beyond them (clipped).
		std::vector<int> levels;
		std::vector<LevelRect> rects;
		for (int k = 0; k < 5; k++) {
			const int i = int(rng() % scales.count);
			const int h = scales.levels[i].height, w = scales.levels[i].width;
			int r0 = int(rng() % h), r1 = r0 + 1 + int(rng() % 6);
			int c0 = int(rng() % w), c1 = c0 + 1 + int(rng() % 6);
			if (k == 1 && pass == 1)
				c0 = 0;
			if (k == 2 && pass == 1)
				c1 = w + 2, r0 = 0;
			levels.push_back(i);
			rects.push_back(LevelRect{ CellRange{ r0, r1 }, CellRange{ c0, c1 } });
		}
		const long before = part.rectsComputed;
		ASSERT_TRUE(part.compute(input, PyramidDemand::of(levels.data(), rects.data(), int(rects.size()))).ok());
		if (pass == 0) {
			EXPECT_GT(part.rectsComputed, before);
		}
		for (size_t k = 0; k < rects.size(); k++) {
			const int i = levels[k];
			const int h = scales.levels[i].height, w = scales.levels[i].width;
			const CellRange rows = rects[k].rows.clipped(h), cols = rects[k].cols.clipped(w);
			const LevelChannels a = full.prepare(i);
			std::vector<uint16_t> expected(a.data, a.data + kChannelCount * a.planeStride);
			const LevelRect read{ rows, cols };
			const LevelChannels b = part.prepare(i, &read, 1);
			const int padW = full.padCellsW(), padH = full.padCellsH();
			const int y0 = rows.begin == 0 ? 0 : rows.begin + padH;
			const int y1 = rows.end == h ? b.paddedHeight : rows.end + padH;
			const int x0 = cols.begin == 0 ? 0 : cols.begin + padW;
			const int x1 = cols.end == w ? b.paddedWidth : cols.end + padW;
			int mismatches = 0;
			for (int c = 0; c < kChannelCount; c++)
				for (int y = y0; y < y1; y++)
					for (int x = x0; x < x1; x++) {
						const size_t q = size_t(c) * a.planeStride + size_t(y) * a.rowStride + x;
						if (expected[q] != b.data[q] && mismatches++ < 3)
							ADD_FAILURE() << "pass " << pass << " level " << i << " channel " << c
								      << " padded (" << y << ", " << x << ") rows "
								      << rows.begin << ".." << rows.end << " cols "
								      << cols.begin << ".." << cols.end;
					}
			ASSERT_EQ(mismatches, 0);
		}
	}
	EXPECT_GT(part.computedCount, 0);
}

TEST(PyramidBands, RectanglesEqualTheFullPyramid)
{
	// Odd sizes; RGB8 and a format converted a strip of rows at a time.
	const int width = 2 * 160 + 1, height = 2 * 124 - 1;
	for (uint32_t seed = 1; seed <= 12; seed++) {
		SCOPED_TRACE(seed);
		const std::vector<uint8_t> rgb = test::randomImage(70 + seed, width, height);
		compareRectangles(rgb, width, height, seed * 41, seed % 2 ? PixelFormat::RGB8 : PixelFormat::NV12);
	}
}

TEST(PyramidBands, RectanglesMergeNearNeighbours)
{
	// addMerged keeps rectangles apart by at least the gap, covering all that was added.
	std::mt19937 rng(9);
	for (int trial = 0; trial < 200; trial++) {
		LevelRect set[6];
		int count = 0;
		std::vector<LevelRect> added;
		for (int k = 0; k < 20; k++) {
			const int r0 = int(rng() % 100), c0 = int(rng() % 100);
			const LevelRect r{ CellRange{ r0, r0 + 1 + int(rng() % 10) }, CellRange{ c0, c0 + 1 + int(rng() % 10) } };
			addMerged(set, count, 6, r, 2);
			added.push_back(r);
			ASSERT_LE(count, 6);
			for (const LevelRect &a : added) {
				bool covered = false;
				for (int q = 0; q < count; q++)
					covered |= set[q].contains(a);
				ASSERT_TRUE(covered);
			}
			for (int q = 0; q < count; q++)
				for (int o = q + 1; o < count; o++)
					ASSERT_FALSE(set[q].near(set[o], 2));
		}
	}
}

TEST(PyramidBands, ToolboxOctavesTakeOneDemandPerFrame)
{
	// The toolbox's octaves resample the smaller ones from the half-size image, which
	// rectangles do not rebuild: a frame's first demand is computed in full-width bands,
	// and a later one outside it is refused by name instead of returning stale channels.
	const int width = 320, height = 240;
	ModelParams p;
	Pyramid pyr;
	ASSERT_TRUE(pyr.init(p, width, height).ok());
	EXPECT_FALSE(pyr.rectsComputable(width, height));
	const std::vector<uint8_t> rgb = test::randomImage(3, width, height);
	FrameInput input;
	ASSERT_TRUE(input.init(width, height, false).ok());
	input.begin(ImageView::rgb8(rgb.data(), width, height));
	const int level = 0;
	const LevelRect rect{ CellRange{ 0, 5 }, CellRange{ 0, 5 } }, inside{ CellRange{ 1, 4 }, CellRange{ 2, 9 } },
			outside{ CellRange{ 6, 9 }, CellRange{ 0, 5 } };
	pyr.beginFrame();
	ASSERT_TRUE(pyr.compute(input, PyramidDemand::of(&level, &rect, 1)).ok());
	EXPECT_GT(pyr.computedCount, 0);
	EXPECT_EQ(pyr.rectsComputed, 0);
	EXPECT_TRUE(pyr.compute(input, PyramidDemand::of(&level, &inside, 1)).ok());
	const Status st = pyr.compute(input, PyramidDemand::of(&level, &outside, 1));
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("half-size"), std::string::npos) << st.message();
}

TEST(PyramidBands, PlacementIsCheckedAndSizedForTheMaximumFrame)
{
	ModelParams p;
	Pyramid pyr;
	ASSERT_TRUE(pyr.init(p, 200, 150).ok());
	ScaleList scales;
	ASSERT_TRUE(pyr.scalesFor(200, 150, scales).ok());
	int source[kMaxLevels];
	for (int i = 0; i < scales.count; i++)
		source[i] = 1; // every level from level 1, computed
	EXPECT_TRUE(pyr.placeLevels(source, scales.count).ok());
	source[1] = 0; // level 1 from level 0, which is not computed
	EXPECT_EQ(pyr.placeLevels(source, scales.count).code(), ErrorCode::InvalidArgument);
	EXPECT_EQ(pyr.placeLevels(source, scales.count + 1).code(), ErrorCode::InvalidArgument);
	// Every level computed: the channel store grows at setup to hold them all.
	for (int i = 0; i < scales.count; i++)
		source[i] = i;
	ASSERT_TRUE(pyr.placeLevels(source, scales.count).ok());
	const std::vector<uint8_t> rgb = test::randomImage(4, 200, 150);
	ASSERT_TRUE(pyr.compute(rgb.data(), 3 * 200, 200, 150).ok());
	EXPECT_EQ(pyr.computedCount, scales.count);
	// Another frame size keeps the toolbox's octaves.
	ASSERT_TRUE(pyr.compute(rgb.data(), 3 * 200, 180, 150).ok());
	EXPECT_LT(pyr.computedCount, pyr.scales().count);
}

TEST(PyramidBands, ColumnRangesEqualTheFullLevel)
{
	// The calibrated mode's second pass prepares a level only in the rows and columns its
	// new regions' windows read: there it must equal the full level, padding included
	// where the range touches a side. Toolbox octaves and placed levels.
	const int width = 2 * 160 + 1, height = 2 * 124 - 1;
	const std::vector<uint8_t> rgb = test::randomImage(41, width, height);
	ModelParams p;
	for (bool placed : { false, true }) {
		SCOPED_TRACE(placed ? "placed levels" : "octaves");
		Pyramid full, part;
		ASSERT_TRUE(full.init(p, width, height).ok());
		ASSERT_TRUE(part.init(p, width, height).ok());
		ScaleList scales;
		ASSERT_TRUE(full.scalesFor(width, height, scales).ok());
		CellRange all[kMaxLevels];
		for (int i = 0; i < scales.count; i++)
			all[i] = CellRange{ 0, scales.levels[i].height };
		if (placed) {
			int source[kMaxLevels];
			ASSERT_TRUE(choosePlacedLevels(p, scales, all, full.channelMargin(), 5, width,
							 height, source));
			ASSERT_TRUE(full.placeLevels(source, scales.count).ok());
			ASSERT_TRUE(part.placeLevels(source, scales.count).ok());
		}
		ASSERT_TRUE(full.compute(rgb.data(), 3 * width, width, height).ok());
		ASSERT_TRUE(part.compute(rgb.data(), 3 * width, width, height).ok());
		std::mt19937 rng(placed ? 7 : 3);
		for (int i = 0; i < scales.count; i++) {
			const int h = scales.levels[i].height, w = scales.levels[i].width;
			for (int trial = 0; trial < 4; trial++) {
				int r0 = int(rng() % h), r1 = r0 + 1 + int(rng() % (h - r0));
				int c0 = int(rng() % w), c1 = c0 + 1 + int(rng() % (w - c0));
				if (trial == 1)
					c0 = 0; // touching the left side
				if (trial == 2)
					c1 = w, r0 = 0; // the right side and the top
				const CellRange rows{ r0, r1 }, cols{ c0, c1 };
				const LevelChannels a = full.prepare(i);
				std::vector<uint16_t> expected(a.data, a.data + kChannelCount * a.planeStride);
				const LevelRect read{ rows, cols };
				const LevelChannels b = part.prepare(i, &read, 1);
				const int pad = full.padCellsW(), padH = full.padCellsH();
				const int y0 = r0 == 0 ? 0 : r0 + padH, y1 = r1 == h ? b.paddedHeight : r1 + padH;
				const int x0 = c0 == 0 ? 0 : c0 + pad, x1 = c1 == w ? b.paddedWidth : c1 + pad;
				int mismatches = 0;
				for (int c = 0; c < kChannelCount; c++)
					for (int y = y0; y < y1; y++)
						for (int x = x0; x < x1; x++) {
							const size_t k = size_t(c) * a.planeStride + size_t(y) * a.rowStride + x;
							if (expected[k] != b.data[k] && mismatches++ < 3)
								ADD_FAILURE() << "level " << i << " channel " << c << " padded ("
									      << y << ", " << x << ") rows " << r0 << ".." << r1
									      << " cols " << c0 << ".." << c1;
						}
				ASSERT_EQ(mismatches, 0);
			}
		}
	}
}

TEST(PyramidBands, RowsEqualTheFullPyramidFromCameraFormats)
{
	const int width = 317, height = 239;
	const PixelFormat formats[] = { PixelFormat::YUV420, PixelFormat::NV12, PixelFormat::YUYV,
					PixelFormat::BayerGRBG8 };
	for (uint32_t k = 0; k < 4; k++) {
		SCOPED_TRACE(pixelFormatName(formats[k]));
		compareBands(test::randomImage(20 + k, width, height), width, height, 40 + k,
			     formats[k]);
	}
}

TEST(PyramidBands, AnEmptyDemandComputesNothing)
{
	const int width = 200, height = 150;
	const std::vector<uint8_t> rgb = test::randomImage(3, width, height);
	ModelParams p;
	Pyramid pyr;
	ASSERT_TRUE(pyr.init(p, width, height).ok());
	ASSERT_TRUE(pyr.compute(rgb.data(), 3 * width, width, height, PyramidDemand::of(nullptr, nullptr, 0)).ok());
	EXPECT_EQ(pyr.computedCount, 0);
}

} // namespace
} // namespace calped
