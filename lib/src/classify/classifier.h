// SPDX-License-Identifier: BSD-2-Clause
// The boosted trees laid out for one pyramid layout: every feature id resolved once,
// at setup, to an offset into the level buffer (channel, row and column strides are
// fixed for the pyramid's lifetime).
#pragma once

#include <calped/model.h>

#include <vector>

#include "kernels.h"
#include "pyramid/ldcf_filter.h"
#include "pyramid/pyramid.h"

namespace calped {

class Classifier
{
public:
	// rowStride, planeStride: of the levels scan() will see (Pyramid::classifierRowStride()).
	void init(const Model &model, ptrdiff_t rowStride, ptrdiff_t planeStride,
		  const kernels::KernelTable &k = kernels::bestKernels());

	// Windows of one level: returns how many passed the cascade (the first `capacity`
	// are written to hits) and adds the windows evaluated to *windows.
	uint64_t scan(const LevelChannels &level, kernels::WindowHit *hits, uint64_t capacity,
		      uint64_t *windows) const;

	// Only the listed windows (row << 16 | column) of one level.
	uint64_t scanList(const LevelChannels &level, const uint32_t *windows, size_t count,
			  kernels::WindowHit *hits, uint64_t capacity) const;

	// Window rows and columns of a level with this padded size (cells of the channels the
	// trees read: for LDCF the filtered, half-size level), the toolbox's counts.
	void windowGrid(int paddedHeight, int paddedWidth, int &rows, int &cols) const;

	void setCascadeThreshold(float thr);

private:
	// The score of the window whose first cell is `base` in a level computed on demand
	// (LevelChannels::onDemand), reading each feature through it: the reference kernels'
	// walk and soft cascade.
	int32_t scoreOnDemand(LdcfFilter &level, ptrdiff_t base) const;

	ModelParams params_;
	int shrink_ = 4; // pixels per cell of the channels the trees read (Model::classifierShrink)
	const kernels::KernelTable *k_ = nullptr;
	int nTrees_ = 0, nodesPerTree_ = 0;
	bool depth2_ = false;
	int32_t cascThr_ = 0;
	std::vector<kernels::Depth2Tree> depth2Trees_;
	std::vector<kernels::TreeNode> nodes_;
};

} // namespace calped
