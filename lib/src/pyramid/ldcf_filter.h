// SPDX-License-Identifier: BSD-2-Clause
// LDCF's filter stage (the toolbox's acfDetect with opts.filters): a prepared pyramid
// level's ten channels, each replicated nFilters times, convolved with its filter
// (conv2 'same') and resampled to half size (imResample 0.5): the channels LDCF's trees
// read, in biased Q12 (kernels::kLdcfQ, kLdcfBias). Buffers are sized once, in init().
#pragma once

#include <calped/model.h>
#include <calped/status.h>

#include <vector>

#include "channels/channel_computer.h"
#include "core/plane.h"
#include "kernels.h"
#include "pyramid/cell_range.h"
#include "pyramid/level_channels.h"

namespace calped {

class LdcfFilter
{
public:
	// maxHeight x maxWidth: the largest prepared (padded) level it will filter.
	Status init(const Model &model, int maxHeight, int maxWidth,
		    const kernels::KernelTable &k = kernels::bestKernels());

	// The filtered level: 10 * nFilters planes (channel c of filter j is plane j * 10 + c)
	// of round(h / 2) x round(w / 2) cells, with fixed strides. Valid until the next call.
	LevelChannels apply(const LevelChannels &level) { return apply(level, nullptr, 0, 0, 0); }
	// The same where `level` is exact only in these rectangles (cells before its padH x
	// padW padding, as Pyramid::prepare takes them; a rectangle touching the level's edge
	// includes the padding beyond it): each rectangle filtered on its own, and only the
	// outputs that read nothing outside it are written (equal to apply(level)'s there);
	// the rest is stale. rects null: the whole level.
	LevelChannels apply(const LevelChannels &level, const LevelRect *rects, int count, int padH,
			    int padW);

	// The rows (or columns) of a level, before its `pad` cells of padding, that filtered
	// cells [out.begin, out.end) (padded, half size) read: the half-size resampling's taps
	// (at most rows 2o - 1 .. 2o + 2 for output o) and the filter's reach of size / 2 on
	// each side, clipped to the level's `size` cells. The calibrated method grows what
	// its windows read by this, so rectangles give the full level's values.
	static CellRange levelCellsRead(const CellRange &out, int filterSize, int pad, int size);

	// A tree threshold in Q14 (the blob's) as the same split on biased Q12 channels:
	// q12 < ceil(T / 4) exactly when 4 * q12 < T, moved by the bias, clamped to [0, 65536].
	static int32_t thresholdFor(int32_t q14);

	ptrdiff_t rowStride() const { return rowStride_; }
	ptrdiff_t planeStride() const { return planeStride_; }
	// Bytes init() allocates for levels of maxHeight x maxWidth (memory estimates).
	static uint64_t bytesFor(int nFilters, uint64_t maxHeight, uint64_t maxWidth);

private:
	// One rectangle of exact input (padded rows `rows`, columns `cols` of the h x w level).
	void applyRect(const LevelChannels &level, const CellRange &rows, const CellRange &cols);

	const kernels::KernelTable *k_ = nullptr;
	int nFilters_ = 0, size_ = 0;
	std::vector<int32_t> filters_;
	PlaneBuffer<uint16_t> full_; // one filtered channel at the level's size
	PlaneBuffer<uint16_t> tmp_;  // the resampler's row pass
	std::vector<kernels::ResampleTap> xTaps_, yTaps_, xShifted_, yShifted_;
	std::vector<uint16_t> out_;
	int maxHeight_ = 0, maxWidth_ = 0;
	ptrdiff_t rowStride_ = 0, planeStride_ = 0;
};

} // namespace calped
