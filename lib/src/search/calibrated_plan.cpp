// SPDX-License-Identifier: BSD-2-Clause
#include "search/calibrated_plan.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "classify/classifier.h"
#include "pyramid/ldcf_filter.h"

namespace calped {

namespace {

// Pixels per cell of the channels the trees read (Model::classifierShrink: LDCF's filtered
// levels are half size).
int classifierShrink(const ModelParams &p) { return p.nFilters > 0 ? 2 * p.shrink : p.shrink; }

// Cells of a level (before its `pad` cells of padding, clipped to its `size`) that the
// classifier's padded cells `read` depend on: the same cells, or for LDCF what the filter
// stage reads to produce them.
CellRange levelCellsOf(const ModelParams &p, const CellRange &read, int pad, int size)
{
	if (p.nFilters > 0)
		return LdcfFilter::levelCellsRead(read, p.filterSize, pad, size);
	return CellRange{ read.begin - pad, read.end - pad }.clipped(size);
}

// Rows of a level (before padding) read by windows in rows firstRow..lastRow: a window at
// row r reads the classifier's padded rows [r * step, r * step + model height).
CellRange windowRowsRead(const ModelParams &p, int padH, int firstRow, int lastRow, int height)
{
	if (lastRow < firstRow)
		return CellRange();
	const int step = p.stride / classifierShrink(p);
	const int windowRows = p.modelDsPadH / classifierShrink(p);
	return levelCellsOf(p, CellRange{ firstRow * step, lastRow * step + windowRows }, padH, height);
}

// The classifier's padded size of a level whose padded size is n.
int classifierCells(const ModelParams &p, int n) { return p.nFilters > 0 ? (n + 1) / 2 : n; }

} // namespace

Status CalibratedPlan::build(const CameraModel &camera, const ModelParams &params,
			     const ScaleList &scales, const WindowBoxes &boxes, int padH, int padW,
			     const Classifier &classifier, double minHeight, double maxHeight)
{
	if (!camera.valid())
		return Status::error(ErrorCode::InvalidArgument, "calibrated mode needs a valid camera");
	if (!(minHeight > 0 && maxHeight >= minHeight && maxHeight < 10))
		return Status::error(ErrorCode::InvalidArgument,
				     "pedestrian heights %g..%g m are not a range in (0, 10)", minHeight,
				     maxHeight);
	params_ = params;
	padH_ = padH;
	padW_ = padW;
	boxes_ = boxes;
	scales_ = scales;
	// Half a box, in window steps (cells of the level).
	const int sparseRows = std::max(1, int(std::lround(params.modelDsH / 2 / params.stride)));
	const int sparseCols = std::max(1, int(std::lround(params.modelDsW / 2 / params.stride)));
	try {
		windows_.clear();
		sparse_.clear();
		plausible_.clear();
		plausibleFirst_.clear();
		plausibleLast_.clear();
		for (int i = 0; i < scales.count; i++) {
			first_[i] = windows_.size();
			sparseFirst_[i] = sparse_.size();
			gridFirst_[i] = plausible_.size();
			colFirst_[i] = plausibleFirst_.size();
			const PyramidLevel &l = scales.levels[i];
			int rows, cols;
			classifier.windowGrid(classifierCells(params, l.height + 2 * padH),
					      classifierCells(params, l.width + 2 * padW), rows, cols);
			if (rows > 65535 || cols > 65535)
				return Status::error(ErrorCode::InvalidArgument, "level %d too large", i);
			rows_[i] = rows;
			cols_[i] = cols;
			plausible_.resize(plausible_.size() + size_t(rows) * cols, 0);
			uint8_t *grid = plausible_.data() + gridFirst_[i];
			int firstRow = rows, lastRow = -1;
			plausibleFirst_.resize(plausibleFirst_.size() + size_t(cols), rows);
			plausibleLast_.resize(plausibleLast_.size() + size_t(cols), -1);
			for (int c = 0; c < cols; c++)
				for (int r = 0; r < rows; r++) {
					const WindowBox b = boxes.box(l, r, c);
					const Eigen::Vector2d foot(b.x + b.w / 2, b.y + b.h), head(b.x + b.w / 2, b.y);
					const double height = camera.boxWorldHeight(foot, head);
					if (!(height >= minHeight && height <= maxHeight))
						continue;
					const uint32_t packed = uint32_t(r) << 16 | uint32_t(c);
					windows_.push_back(packed);
					grid[size_t(r) * cols + c] = 1;
					const size_t k = colFirst_[i] + size_t(c);
					plausibleFirst_[k] = std::min(plausibleFirst_[k], r);
					plausibleLast_[k] = std::max(plausibleLast_[k], r);
					firstRow = std::min(firstRow, r);
					lastRow = std::max(lastRow, r);
					if (r % sparseRows == 0 && c % sparseCols == 0)
						sparse_.push_back(packed);
				}
			levelRows_[i] = windowRowsRead(params, padH, firstRow, lastRow, l.height);
		}
		first_[scales.count] = windows_.size();
		sparseFirst_[scales.count] = sparse_.size();
		gridFirst_[scales.count] = plausible_.size();
		colFirst_[scales.count] = plausibleFirst_.size();
		windows_.shrink_to_fit();
		sparse_.shrink_to_fit();
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "calibrated window lists");
	}
	return Status::success();
}

CellRange CalibratedPlan::rowsOfWindowRows(int i, int firstRow, int lastRow) const
{
	return windowRowsRead(params_, padH_, firstRow, lastRow, scales_.levels[i].height);
}

CellRange CalibratedPlan::rowsRead(int i, const uint32_t *windows, size_t count) const
{
	int firstRow = rows_[i], lastRow = -1;
	for (size_t k = 0; k < count; k++) {
		const int r = int(windows[k] >> 16);
		firstRow = std::min(firstRow, r);
		lastRow = std::max(lastRow, r);
	}
	return windowRowsRead(params_, padH_, firstRow, lastRow, scales_.levels[i].height);
}

CellRange CalibratedPlan::colsRead(int i, const uint32_t *windows, size_t count) const
{
	int firstCol = cols_[i], lastCol = -1;
	for (size_t k = 0; k < count; k++) {
		const int c = int(windows[k] & 0xFFFF);
		firstCol = std::min(firstCol, c);
		lastCol = std::max(lastCol, c);
	}
	return windowColsRead(i, firstCol, lastCol);
}

CellRange CalibratedPlan::windowColsRead(int i, int firstCol, int lastCol) const
{
	if (lastCol < firstCol)
		return CellRange();
	// A window at column c reads padded columns [c * step, c * step + model width).
	const int step = params_.stride / classifierShrink(params_);
	const int windowCols = params_.modelDsPadW / classifierShrink(params_);
	return levelCellsOf(params_, CellRange{ firstCol * step, lastCol * step + windowCols }, padW_,
			    scales_.levels[i].width);
}

LevelRect CalibratedPlan::windowsRect(int i, int firstRow, int lastRow, int firstCol, int lastCol) const
{
	return LevelRect{ rowsOfWindowRows(i, firstRow, lastRow), windowColsRead(i, firstCol, lastCol) };
}

size_t CalibratedPlan::largestLevelWindows() const
{
	size_t most = 0;
	for (int i = 0; i < scales_.count; i++)
		most = std::max(most, windowCount(i));
	return most;
}

bool CalibratedPlan::windowsInside(int i, float x0, float y0, float x1, float y1, int &r0,
				   int &r1, int &c0, int &c1) const
{
	boxes_.centredIn(scales_.levels[i], x0, y0, x1, y1, r0, r1, c0, c1);
	c0 = std::max(c0, 0);
	r0 = std::max(r0, 0);
	c1 = std::min(c1, cols_[i] - 1);
	r1 = std::min(r1, rows_[i] - 1);
	return c0 <= c1 && r0 <= r1;
}

} // namespace calped
