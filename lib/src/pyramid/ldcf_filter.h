// SPDX-License-Identifier: BSD-2-Clause
// LDCF's filter stage (the toolbox's acfDetect with opts.filters): a prepared pyramid
// level's ten channels, each replicated nFilters times, convolved with its filter
// (conv2 'same') and resampled to half size (imResample 0.5): the channels LDCF's trees
// read, in biased Q12 (kernels::kLdcfQ, kLdcfBias). Buffers are sized once, in init().
#pragma once

#include <calped/model.h>
#include <calped/status.h>

#include <vector>

#include "core/plane.h"
#include "kernels.h"
#include "pyramid/pyramid.h"

namespace calped {

class LdcfFilter
{
public:
	// maxHeight x maxWidth: the largest prepared (padded) level it will filter.
	Status init(const Model &model, int maxHeight, int maxWidth,
		    const kernels::KernelTable &k = kernels::bestKernels());

	// The filtered level: 10 * nFilters planes (channel c of filter j is plane j * 10 + c)
	// of round(h / 2) x round(w / 2) cells, with fixed strides. Valid until the next call.
	LevelChannels apply(const LevelChannels &level);

	// A tree threshold in Q14 (the blob's) as the same split on biased Q12 channels:
	// q12 < ceil(T / 4) exactly when 4 * q12 < T, moved by the bias, clamped to [0, 65536].
	static int32_t thresholdFor(int32_t q14);

	ptrdiff_t rowStride() const { return rowStride_; }
	ptrdiff_t planeStride() const { return planeStride_; }

private:
	const kernels::KernelTable *k_ = nullptr;
	int nFilters_ = 0, size_ = 0;
	std::vector<int32_t> filters_;
	PlaneBuffer<uint16_t> full_; // one filtered channel at the level's size
	PlaneBuffer<uint16_t> tmp_;  // the resampler's row pass
	std::vector<kernels::ResampleTap> xTaps_, yTaps_;
	std::vector<uint16_t> out_;
	int maxHeight_ = 0, maxWidth_ = 0;
	ptrdiff_t rowStride_ = 0, planeStride_ = 0;
};

} // namespace calped
