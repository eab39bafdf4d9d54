// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/ldcf_filter.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace calped {

namespace {

// imResample(C, .5): round(n / 2) samples, Matlab's rounding (halves away from zero).
int halfSize(int n) { return (n + 1) / 2; }

} // namespace

Status LdcfFilter::init(const Model &model, int maxHeight, int maxWidth, const kernels::KernelTable &k)
{
	const ModelParams &p = model.params;
	if (p.nFilters <= 0 || p.filterSize <= 0 ||
	    model.filters.size() != size_t(p.nFilters) * kChannelCount * p.filterSize * p.filterSize)
		return Status::error(ErrorCode::InvalidArgument, "the model has no LDCF filters");
	if (maxHeight < 1 || maxWidth < 1)
		return Status::error(ErrorCode::InvalidArgument, "level size %dx%d", maxWidth, maxHeight);
	k_ = &k;
	nFilters_ = p.nFilters;
	size_ = p.filterSize;
	maxHeight_ = maxHeight;
	maxWidth_ = maxWidth;
	try {
		filters_ = model.filters;
		full_.allocate(maxWidth, maxHeight);
		tmp_.allocate(halfSize(maxWidth), maxHeight);
		xTaps_.resize(size_t(halfSize(maxWidth)) + 1);
		yTaps_.resize(size_t(halfSize(maxHeight)) + 1);
		rowStride_ = halfSize(maxWidth);
		planeStride_ = rowStride_ * halfSize(maxHeight);
		out_.assign(size_t(planeStride_) * kChannelCount * nFilters_, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "LDCF buffers for %dx%d levels", maxWidth,
				     maxHeight);
	}
	return Status::success();
}

LevelChannels LdcfFilter::apply(const LevelChannels &level)
{
	LevelChannels out;
	const int h = level.paddedHeight, w = level.paddedWidth;
	if (!k_ || h < 1 || w < 1 || h > maxHeight_ || w > maxWidth_)
		return out;
	const int mh = halfSize(h), mw = halfSize(w);
	// The bias passes through the resampler exactly: its weights sum to 2^14.
	if (!kernels::buildResampleTaps(w, mw, 1.0, xTaps_.data()) ||
	    !kernels::buildResampleTaps(h, mh, 1.0, yTaps_.data()))
		return out;
	const Plane<uint16_t> full = full_.view(w, h);
	const Plane<uint16_t> tmp = tmp_.view(mw, h);
	const int taps = size_ * size_;
	for (int j = 0; j < nFilters_; j++)
		for (int c = 0; c < kChannelCount; c++) {
			const int plane = j * kChannelCount + c;
			k_->ldcfFilter(level.data + c * level.planeStride, level.rowStride, w, h,
				       filters_.data() + size_t(plane) * taps, size_, full.data, full.stride);
			k_->resamplePlane(full.data, full.stride, w, h, out_.data() + plane * planeStride_,
					  rowStride_, mw, mh, xTaps_.data(), yTaps_.data(), tmp.data,
					  tmp.stride);
		}
	out.data = out_.data();
	out.paddedHeight = mh;
	out.paddedWidth = mw;
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	return out;
}

int32_t LdcfFilter::thresholdFor(int32_t q14)
{
	// ceil(T / 4) for any sign, in 64 bits (T may be INT32_MIN or INT32_MAX).
	const int64_t t = q14;
	const int64_t q12 = t >= 0 ? (t + 3) / 4 : -((-t) / 4);
	return int32_t(std::clamp<int64_t>(q12 + kernels::kLdcfBias, 0, 65536));
}

} // namespace calped
