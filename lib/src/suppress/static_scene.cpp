// SPDX-License-Identifier: BSD-2-Clause
#include "suppress/static_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <new>

namespace calped {

Status StaticScene::init(int maxWidth, int maxHeight, const StaticRejection &settings)
{
	settings_ = settings;
	try {
		const size_t cells = size_t(maxWidth / 4 + 1) * size_t(maxHeight / 4 + 1);
		current_.assign(cells, 0);
		background_.assign(cells, 0);
		columnSums_.assign(size_t(maxWidth) * 3 + 12, 0);
		table_.assign(size_t(maxWidth / 4 + 2) * size_t(maxHeight / 4 + 2), 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "static rejection buffers");
	}
	cellsW_ = cellsH_ = 0;
	frames_ = 0;
	return Status::success();
}

void StaticScene::observe(FrameInput &input)
{
	const int w = input.width() / 4, h = input.height() / 4;
	if (w != cellsW_ || h != cellsH_) {
		cellsW_ = w;
		cellsH_ = h;
		frames_ = 0;
	}
	// Grey (R + 2G + B) / 4, averaged over each 4x4 cell: a sum of 64 weights. The four
	// rows' bytes are added first (contiguous, so the compiler vectorises it), then each
	// cell weighs its 12 column sums.
	uint16_t *sums = columnSums_.data();
	const int bytes = 12 * w;
	for (int cy = 0; cy < h; cy++) {
		ptrdiff_t stride;
		const uint8_t *rows = input.rows(4 * cy, 4, stride);
		const uint8_t *r0 = rows, *r1 = rows + stride, *r2 = r1 + stride, *r3 = r2 + stride;
		for (int i = 0; i < bytes; i++)
			sums[i] = uint16_t(r0[i] + r1[i] + r2[i] + r3[i]);
		uint8_t *out = current_.data() + size_t(cy) * w;
		for (int cx = 0; cx < w; cx++) {
			const uint16_t *p = sums + 12 * cx;
			uint32_t sum = 0;
			for (int dx = 0; dx < 4; dx++)
				sum += p[3 * dx] + 2u * p[3 * dx + 1] + p[3 * dx + 2];
			out[cx] = uint8_t(sum / 64);
		}
	}
	if (frames_ == 0)
		std::copy(current_.begin(), current_.begin() + size_t(w) * h, background_.begin());
	// The summed-area table of the cells that differ.
	uint32_t *t = table_.data();
	const size_t tw = size_t(w) + 1;
	std::fill(t, t + tw, 0u);
	for (int cy = 0; cy < h; cy++) {
		const uint8_t *cur = current_.data() + size_t(cy) * w;
		const uint8_t *bg = background_.data() + size_t(cy) * w;
		const uint32_t *above = t + size_t(cy) * tw;
		uint32_t *row = t + size_t(cy + 1) * tw;
		uint32_t inRow = 0;
		row[0] = 0;
		for (int cx = 0; cx < w; cx++) {
			inRow += std::abs(int(cur[cx]) - int(bg[cx])) > settings_.difference;
			row[cx + 1] = above[cx + 1] + inRow;
		}
	}
}

StaticScene::CellRect StaticScene::cellsOf(const Detection &box, int cellsW, int cellsH)
{
	CellRect c;
	c.x0 = std::clamp(int(std::floor(box.x / 4)), 0, cellsW - 1);
	c.x1 = std::clamp(int(std::floor((box.x + box.w) / 4)), 0, cellsW - 1);
	c.y0 = std::clamp(int(std::floor(box.y / 4)), 0, cellsH - 1);
	c.y1 = std::clamp(int(std::floor((box.y + box.h) / 4)), 0, cellsH - 1);
	return c;
}

float StaticScene::foreground(const Detection &box) const
{
	if (cellsW_ == 0 || cellsH_ == 0)
		return 1.0f;
	const CellRect cells = cellsOf(box, cellsW_, cellsH_);
	return float(foregroundCells(cells)) / float(cells.count());
}

int StaticScene::reject(Detection *detections, int count)
{
	if (!ready())
		return count;
	int kept = 0;
	for (int i = 0; i < count; i++)
		if (cellsW_ == 0 || moving(cellsOf(detections[i], cellsW_, cellsH_)))
			detections[kept++] = detections[i];
	return kept;
}

void StaticScene::update()
{
	const size_t n = size_t(cellsW_) * cellsH_;
	for (size_t i = 0; i < n; i++)
		background_[i] += current_[i] > background_[i] ? 1 : (current_[i] < background_[i] ? -1 : 0);
	frames_++;
}

} // namespace calped
