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
	// of round(h / 2) x round(w / 2) cells, with fixed strides, every cell computed (the
	// SIMD filter and resampler kernels). Valid until the next call.
	LevelChannels apply(const LevelChannels &level);

	// The same level computed on demand: each cell computed when at() first reads it, as
	// apply() computes it, and remembered until the next call. For windows that read a
	// few percent of the cells (the calibrated method's: docs/calibrated.md). `level` must
	// stay as it is while the result is read, and be exact wherever the cells read reach
	// with their filter and resampling taps (LdcfFilter::levelCellsRead).
	LevelChannels onDemand(const LevelChannels &level);
	// Cell `index` (plane * planeStride() + row * rowStride() + column) of onDemand()'s level.
	uint16_t at(ptrdiff_t index)
	{
		return stamp_[size_t(index)] == generation_ ? out_[size_t(index)] : compute(index);
	}

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
	// Taps of the half-size resampling of an h x w level (false: beyond the resampler).
	bool buildTaps(int h, int w);
	// A cell of onDemand()'s level, computed (kernels::ldcfCell) and remembered.
	uint16_t compute(ptrdiff_t index);

	const kernels::KernelTable *k_ = nullptr;
	int nFilters_ = 0, size_ = 0;
	std::vector<int32_t> filters_;
	// Each plane's filter in ldcfCell's vector layout (kernels::packLdcfCellFilter), and
	// whether every plane's could be packed: if one cannot (a weight of +1.0), none is
	// used and every cell takes the reference kernel.
	std::vector<int16_t> packed_;
	bool isPacked_ = false;
	PlaneBuffer<uint16_t> full_; // one filtered channel at the level's size
	PlaneBuffer<uint16_t> tmp_;  // the resampler's row pass
	std::vector<kernels::ResampleTap> xTaps_, yTaps_;
	std::vector<uint16_t> out_;
	// onDemand(): the level read, and which cells of out_ hold its values (stamp equal to
	// the generation, a new one per call; all cleared when it wraps).
	LevelChannels source_;
	std::vector<uint8_t> stamp_;
	uint8_t generation_ = 0;
	int maxHeight_ = 0, maxWidth_ = 0;
	ptrdiff_t rowStride_ = 0, planeStride_ = 0;
};

} // namespace calped
