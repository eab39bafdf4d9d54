// SPDX-License-Identifier: BSD-2-Clause
// Static-scene rejection for fixed cameras (beyond the thesis): a background of the
// frame's 4x4-pixel grey cells, kept as an approximate running median (each frame moves
// every cell one grey level towards what it sees), and a test that a detection's box
// holds enough cells that differ from it. A tripod or a sign that looks like a person is
// found in the same place frame after frame; its box never differs from the background.
#pragma once

#include <calped/detector.h>
#include <calped/status.h>

#include <cstdint>
#include <vector>

#include "input/frame_input.h"

namespace calped {

class StaticScene
{
public:
	// Cells [x0, x1] x [y0, y1] of the frame's grid, inclusive.
	struct CellRect {
		int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
		int count() const { return (x1 - x0 + 1) * (y1 - y0 + 1); }
	};
	// The cells a box (input pixels) touches in a grid of cellsW x cellsH cells, clipped.
	static CellRect cellsOf(const Detection &box, int cellsW, int cellsH);

	// Buffers for frames up to maxWidth x maxHeight (settings checked by
	// DetectorConfig::validate()).
	Status init(int maxWidth, int maxHeight, const StaticRejection &settings);

	// The grey cells of this frame (read from `input` a strip at a time), and which of
	// them differ from the background (counted in a summed-area table). A frame of
	// another size than the last one starts the background again.
	void observe(FrameInput &input);

	// Removes (in place, order kept) the detections whose boxes have fewer than
	// settings.minForeground of their cells differing from the background by more than
	// settings.difference; none in the first warmupFrames frames of a background.
	// Returns how many are left.
	int reject(Detection *detections, int count);

	// The background takes one grey level's step towards this frame.
	void update();

	// Cells of the last frame, and whether the background is trusted yet.
	int cellsWide() const { return cellsW_; }
	int cellsHigh() const { return cellsH_; }
	bool ready() const { return frames_ >= settings_.warmupFrames; }
	// Grey level of cell (cx, cy) of the last frame (tests).
	uint8_t cellGrey(int cx, int cy) const { return current_[size_t(cy) * cellsW_ + cx]; }
	// Fraction of the box's cells that differ from the background (tests, tools).
	float foreground(const Detection &box) const;
	// Whether at least minForeground of these cells differ from the background (the
	// test reject() applies to a detection's box).
	bool moving(const CellRect &cells) const
	{
		return float(foregroundCells(cells)) / float(cells.count()) >= settings_.minForeground;
	}
	// Cells of `cells` that differ from the background, from the summed-area table.
	int foregroundCells(const CellRect &cells) const
	{
		const size_t w = size_t(cellsW_) + 1;
		const uint32_t *t = table_.data();
		return int(t[size_t(cells.y1 + 1) * w + size_t(cells.x1 + 1)] -
			   t[size_t(cells.y0) * w + size_t(cells.x1 + 1)] -
			   t[size_t(cells.y1 + 1) * w + size_t(cells.x0)] + t[size_t(cells.y0) * w + size_t(cells.x0)]);
	}

private:
	StaticRejection settings_;
	std::vector<uint8_t> current_, background_;
	std::vector<uint16_t> columnSums_; // one strip of four rows, added byte by byte
	// Summed-area table of the differing cells: (cellsW_ + 1) x (cellsH_ + 1), a zero
	// row and column first.
	std::vector<uint32_t> table_;
	int cellsW_ = 0, cellsH_ = 0;
	long frames_ = 0; // frames the background has seen
};

} // namespace calped
