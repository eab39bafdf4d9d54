// SPDX-License-Identifier: BSD-2-Clause
// The toolbox's chnsCompute for one pyramid scale: from LUV planes at full resolution
// to the ten aggregated channels (L, U, V, gradient magnitude, six orientations),
// each 1/shrink of the size in both directions (shrink 4 or 2).
#pragma once

#include <calped/model.h>

#include "core/plane.h"
#include "kernels.h"

namespace calped {

constexpr int kChannelCount = 10;

class ChannelComputer
{
public:
	// Allocates scratch for LUV images up to maxWidth x maxHeight pixels.
	void init(const ModelParams &params, int maxWidth, int maxHeight,
		  const kernels::KernelTable &k);

	// luv: three Q16 planes of width x height (multiples of shrink, within the maximum);
	// out: ten planes of width/shrink x height/shrink.
	void compute(const Plane<const uint16_t> luv[3], int width, int height,
		     const Plane<uint16_t> out[kChannelCount]);


private:
	ModelParams params_;
	const kernels::KernelTable *k_ = nullptr;
	kernels::GradientTables grad_;
	PlaneBuffer<uint16_t> smoothed_[3];
	PlaneBuffer<uint16_t> mag_, orient_;
	PlaneBuffer<uint32_t> magSum_;
	std::vector<uint32_t> rowTmp_;
	PlaneBuffer<uint32_t> triScratch_; // zero pages until a block reaches them
	std::vector<int32_t> gradScratch_;
};

} // namespace calped
