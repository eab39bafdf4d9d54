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

#include "channels/frame_input.h"

namespace calped {

class StaticScene
{
public:
	// Buffers for frames up to maxWidth x maxHeight; checks the settings.
	Status init(int maxWidth, int maxHeight, const StaticRejection &settings);

	// The grey cells of this frame (read from `input` a strip at a time). A frame of
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

private:
	StaticRejection settings_;
	std::vector<uint8_t> current_, background_;
	std::vector<uint16_t> columnSums_; // one strip of four rows, added byte by byte
	int cellsW_ = 0, cellsH_ = 0;
	long frames_ = 0; // frames the background has seen
};

} // namespace calped
