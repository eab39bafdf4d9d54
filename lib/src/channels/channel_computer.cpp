// SPDX-License-Identifier: BSD-2-Clause
#include "channels/channel_computer.h"

#include <algorithm>

namespace calped {

void ChannelComputer::init(const ModelParams &params, int maxWidth, int maxHeight,
			   const kernels::KernelTable &k)
{
	params_ = params;
	k_ = &k;
	triScratch_.allocate(int(kernels::triSumScratchSize(maxWidth, maxHeight, params.gradNormRad)), 1);
	kernels::buildGradientTables(grad_, params.nOrients, params.gradNormRad,
				     params.gradNormConst);
	for (auto &p : smoothed_)
		p.allocate(maxWidth, maxHeight);
	mag_.allocate(maxWidth, maxHeight);
	orient_.allocate(maxWidth, maxHeight);
	magSum_.allocate(maxWidth, maxHeight);
	const size_t longest = size_t(std::max(maxWidth, maxHeight));
	// gradHist2's uint64 sums take two words per orientation and cell.
	rowTmp_.assign(std::max(longest, 2 * size_t(params.nOrients) * (maxWidth + 4)), 0);
	gradScratch_.assign(longest * 4 + 16, 0);
}

void ChannelComputer::compute(const Plane<const uint16_t> luv[3], int width, int height,
			      const Plane<uint16_t> out[kChannelCount])
{
	// Colour: smoothed [1 2 1] at full resolution, then averaged over shrink x shrink cells.
	const auto shrink = params_.shrink == 2 ? k_->shrink2 : k_->shrink4;
	const uint16_t *smoothedPlanes[3];
	for (int c = 0; c < 3; c++) {
		Plane<uint16_t> s = smoothed_[c].view(width, height);
		if (params_.colorSmooth > 0)
			k_->smoothTri1(luv[c].data, luv[c].stride, s.data, s.stride, width,
						height, rowTmp_.data());
		else
			for (int y = 0; y < height; y++)
				std::copy(luv[c].row(y), luv[c].row(y) + width, s.row(y));
		shrink(s.data, s.stride, width, height, out[c].data, out[c].stride,
		       kernels::kLuvQ - kernels::kQ, rowTmp_.data());
		smoothedPlanes[c] = s.data;
	}

	// Gradient magnitude (max over colour channels) and orientation.
	Plane<uint16_t> mag = mag_.view(width, height);
	Plane<uint16_t> orient = orient_.view(width, height);
	k_->gradMagOrient(grad_, smoothedPlanes, width, width, height, mag.data,
				   orient.data, mag.stride, gradScratch_.data());

	// Normalised by its own local average: M / (convTri(M, normRad) + normConst).
	if (params_.gradNormRad > 0) {
		Plane<uint32_t> sum = magSum_.view(width, height);
		k_->triSum(mag.data, mag.stride, sum.data, sum.stride, width, height,
			   params_.gradNormRad, triScratch_.data());
		k_->normalizeMag(grad_, mag.data, mag.stride, sum.data, sum.stride,
					  width, height);
	}
	// Normalisation already produced Q14; a raw magnitude is still Q16.
	const int magShift = params_.gradNormRad > 0 ? 0 : kernels::kLuvQ - kernels::kQ;
	shrink(mag.data, mag.stride, width, height, out[3].data, out[3].stride, magShift,
	       rowTmp_.data());

	uint16_t *hist[16];
	for (int o = 0; o < params_.nOrients; o++)
		hist[o] = out[4 + o].data;
	// softBin >= 0 interpolates between orientations; odd softBin also between cells
	// (only with shrink 2: Pyramid::init refuses it with 4).
	if (params_.shrink == 2)
		k_->gradHist2(mag.data, orient.data, mag.stride, width, height, params_.nOrients,
			      params_.softBin >= 0, params_.softBin % 2 != 0, hist, out[4].stride,
			      rowTmp_.data());
	else
		k_->gradHist4(mag.data, orient.data, mag.stride, width, height, params_.nOrients,
			      params_.softBin >= 0, hist, out[4].stride, rowTmp_.data());
}

} // namespace calped
