// SPDX-License-Identifier: BSD-2-Clause
// The calibrated mode's setup (thesis 3.1, and the world-height test of 3.2): for one
// frame size, the pyramid levels and, in each, the windows whose box would hold a person
// of plausible world height. Computed once per camera and configuration.
#pragma once

#include <calped/calibration.h>
#include <calped/model.h>
#include <calped/status.h>

#include <cstdint>
#include <vector>

#include "pyramid/cell_range.h"
#include "pyramid/scales.h"
#include "search/window_boxes.h"

namespace calped {

class Classifier;

class CalibratedPlan
{
public:
	// scales: the pyramid of the (resized) frame; boxes: its windows' boxes; padH, padW:
	// padding in cells.
	Status build(const CameraModel &camera, const ModelParams &params, const ScaleList &scales,
		     const WindowBoxes &boxes, int padH, int padW, const Classifier &classifier,
		     double minHeight, double maxHeight);

	bool levelNeeded(int i) const { return first_[i + 1] > first_[i]; }
	// The rows of level i (before padding) that its plausible windows read; empty when
	// the level has none.
	CellRange levelRows(int i) const { return levelRows_[i]; }
	// The rows of level i that windows in window rows firstRow..lastRow read.
	CellRange rowsOfWindowRows(int i, int firstRow, int lastRow) const;
	// The rows of level i that these windows (row << 16 | column) read.
	CellRange rowsRead(int i, const uint32_t *windows, size_t count) const;
	// The columns of level i (before padding) that they read, as a range.
	CellRange colsRead(int i, const uint32_t *windows, size_t count) const;
	// The cells (rows and columns of level i before padding) that the windows of rows
	// firstRow..lastRow and columns firstCol..lastCol read.
	LevelRect windowsRect(int i, int firstRow, int lastRow, int firstCol, int lastCol) const;
	// Windows of level i, packed row << 16 | column, columns outer (the toolbox's order).
	const uint32_t *windows(int i) const { return windows_.data() + first_[i]; }
	size_t windowCount(int i) const { return first_[i + 1] - first_[i]; }
	size_t largestLevelWindows() const;

	// Thesis 3.2.1: the sparse windows of level i, a grid stepping half a box across and
	// down (so neighbours share half their area), of the plausible ones.
	const uint32_t *sparseWindows(int i) const { return sparse_.data() + sparseFirst_[i]; }
	size_t sparseCount(int i) const { return sparseFirst_[i + 1] - sparseFirst_[i]; }

	// Window grid of level i and whether window (row, col) is plausible.
	int rows(int i) const { return rows_[i]; }
	int cols(int i) const { return cols_[i]; }
	bool plausible(int i, int row, int col) const
	{
		return plausible_[gridFirst_[i] + size_t(row) * cols_[i] + col] != 0;
	}
	// The plausible windows of column col of level i lie in rows [first, last] (first >
	// last when the column has none); rows between may still be implausible.
	void plausibleRows(int i, int col, int &first, int &last) const
	{
		const size_t k = colFirst_[i] + size_t(col);
		first = plausibleFirst_[k];
		last = plausibleLast_[k];
	}
	size_t gridSize() const { return plausible_.size(); }
	size_t gridFirst(int i) const { return gridFirst_[i]; }

	// The window rows and columns of level i whose box centre lies in the input-image
	// rectangle [x0, x1] x [y0, y1]; false if none.
	bool windowsInside(int i, float x0, float y0, float x1, float y1, int &r0, int &r1, int &c0,
			   int &c1) const;

private:
	CellRange windowColsRead(int i, int firstCol, int lastCol) const;
	ModelParams params_;
	WindowBoxes boxes_;
	ScaleList scales_;
	std::vector<uint32_t> windows_, sparse_;
	std::vector<uint8_t> plausible_;
	std::vector<int32_t> plausibleFirst_, plausibleLast_; // per column of every level
	size_t colFirst_[kMaxLevels + 1] = {};
	size_t first_[kMaxLevels + 1] = {}, sparseFirst_[kMaxLevels + 1] = {};
	size_t gridFirst_[kMaxLevels + 1] = {};
	int rows_[kMaxLevels] = {}, cols_[kMaxLevels] = {};
	CellRange levelRows_[kMaxLevels];
	int padH_ = 0, padW_ = 0;
};

} // namespace calped
