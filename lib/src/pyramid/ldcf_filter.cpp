// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/ldcf_filter.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "model/blob_format.h"

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
	for (int32_t f : model.filters)
		if (f < -blob::kMaxFilterWeight || f > blob::kMaxFilterWeight) // the loader's range, ldcfCell's contract
			return Status::error(ErrorCode::InvalidArgument, "LDCF filter weight %d beyond 2^15", int(f));
	k_ = &k;
	nFilters_ = p.nFilters;
	size_ = p.filterSize;
	maxHeight_ = maxHeight;
	maxWidth_ = maxWidth;
	try {
		filters_ = model.filters;
		const size_t planes = size_t(nFilters_) * kChannelCount;
		packed_.assign(planes * kernels::kLdcfPackedCount, 0);
		isPacked_ = true;
		for (size_t plane = 0; plane < planes && isPacked_; plane++)
			isPacked_ = kernels::packLdcfCellFilter(filters_.data() + plane * size_ * size_, size_,
								packed_.data() + plane * kernels::kLdcfPackedCount);
		full_.allocate(maxWidth, maxHeight);
		tmp_.allocate(halfSize(maxWidth), maxHeight);
		xTaps_.resize(size_t(halfSize(maxWidth)) + 1);
		yTaps_.resize(size_t(halfSize(maxHeight)) + 1);
		rowStride_ = halfSize(maxWidth);
		planeStride_ = rowStride_ * halfSize(maxHeight);
		if (uint64_t(planeStride_) * kChannelCount * nFilters_ > UINT32_MAX)
			return Status::error(ErrorCode::InvalidArgument, "LDCF levels of %dx%d: too many filtered cells",
					     maxWidth, maxHeight);
		out_.assign(size_t(planeStride_) * kChannelCount * nFilters_, 0);
		stamp_.assign(out_.size(), 0);
		generation_ = 0;
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "LDCF buffers for %dx%d levels", maxWidth,
				     maxHeight);
	}
	return Status::success();
}

uint64_t LdcfFilter::bytesFor(int nFilters, uint64_t maxHeight, uint64_t maxWidth)
{
	// As init() sizes them: the filtered level and the row pass (uint16), the half-size
	// output planes (uint16) with a stamp each (uint8), two tap arrays and the packed filters.
	const uint64_t halfH = (maxHeight + 1) / 2, halfW = (maxWidth + 1) / 2;
	const uint64_t outputs = halfH * halfW * uint64_t(kChannelCount) * uint64_t(nFilters);
	const uint64_t planes = maxHeight * maxWidth + halfW * maxHeight + outputs;
	const uint64_t packed = uint64_t(nFilters) * kChannelCount * kernels::kLdcfPackedCount;
	return 2 * planes + outputs + (halfW + halfH + 2) * sizeof(kernels::ResampleTap) + 2 * packed;
}

LevelChannels LdcfFilter::apply(const LevelChannels &level)
{
	LevelChannels out;
	const int h = level.paddedHeight, w = level.paddedWidth;
	if (!k_ || h < 1 || w < 1 || h > maxHeight_ || w > maxWidth_ || !buildTaps(h, w))
		return out;
	const int mh = halfSize(h), mw = halfSize(w);
	const Plane<uint16_t> full = full_.view(w, h);
	const int taps = size_ * size_;
	for (int j = 0; j < nFilters_; j++)
		for (int c = 0; c < kChannelCount; c++) {
			const int plane = j * kChannelCount + c;
			k_->ldcfFilter(level.data + c * level.planeStride, level.rowStride, w, h,
				       filters_.data() + size_t(plane) * taps, size_, full.row(0), full.stride);
			k_->resamplePlane(full.row(0), full.stride, w, h, out_.data() + plane * planeStride_,
					  rowStride_, mw, mh, xTaps_.data(), yTaps_.data(), tmp_.data(), mw);
		}
	out.data = out_.data();
	out.paddedHeight = mh;
	out.paddedWidth = mw;
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	return out;
}

bool LdcfFilter::buildTaps(int h, int w)
{
	// The bias passes through the resampler exactly: its weights sum to 2^14.
	return kernels::buildResampleTaps(w, halfSize(w), 1.0, xTaps_.data()) &&
	       kernels::buildResampleTaps(h, halfSize(h), 1.0, yTaps_.data());
}

LevelChannels LdcfFilter::onDemand(const LevelChannels &level)
{
	LevelChannels out;
	const int h = level.paddedHeight, w = level.paddedWidth;
	if (!k_ || h < 1 || w < 1 || h > maxHeight_ || w > maxWidth_ || !buildTaps(h, w))
		return out;
	// A new generation: nothing of out_ is this level's yet.
	if (++generation_ == 0) {
		std::fill(stamp_.begin(), stamp_.end(), uint8_t(0));
		generation_ = 1;
	}
	source_ = level;
	out.data = out_.data();
	out.paddedHeight = halfSize(h);
	out.paddedWidth = halfSize(w);
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	out.onDemand = this;
	return out;
}

uint16_t LdcfFilter::compute(ptrdiff_t index)
{
	// 32-bit divisions (init() keeps every index below 2^32): several times faster than
	// 64-bit ones on the x86 cores measured, and this runs once per cell.
	const uint32_t at = uint32_t(index), planeStride = uint32_t(planeStride_), rowStride = uint32_t(rowStride_);
	const int plane = int(at / planeStride);
	const uint32_t inPlane = at - uint32_t(plane) * planeStride;
	const int oy = int(inPlane / rowStride), ox = int(inPlane - uint32_t(oy) * rowStride);
	uint16_t v = 0;
	// Cells outside the level (no window reads them) stay 0.
	if (oy < halfSize(source_.paddedHeight) && ox < halfSize(source_.paddedWidth)) {
		// apply()'s two steps for this cell alone.
		const uint16_t *channel = source_.data + (plane % kChannelCount) * source_.planeStride;
		const kernels::LdcfCellFilter filter{
			filters_.data() + size_t(plane) * size_ * size_, size_,
			isPacked_ ? packed_.data() + size_t(plane) * kernels::kLdcfPackedCount : nullptr
		};
		v = k_->ldcfCell(channel, source_.rowStride, source_.paddedWidth, source_.paddedHeight,
				 filter, xTaps_[size_t(ox)], yTaps_[size_t(oy)]);
	}
	out_[size_t(index)] = v;
	stamp_[size_t(index)] = generation_;
	return v;
}

CellRange LdcfFilter::levelCellsRead(const CellRange &out, int filterSize, int pad, int size)
{
	if (out.empty())
		return CellRange{};
	const int reach = filterSize / 2;
	return CellRange{ 2 * out.begin - 1 - reach - pad, 2 * out.end + 1 + reach - pad }.clipped(size);
}

int32_t LdcfFilter::thresholdFor(int32_t q14)
{
	// ceil(T / 4) for any sign, in 64 bits (T may be INT32_MIN or INT32_MAX).
	const int64_t t = q14;
	const int64_t q12 = t >= 0 ? (t + 3) / 4 : -((-t) / 4);
	return int32_t(std::clamp<int64_t>(q12 + kernels::kLdcfBias, 0, 65536));
}

} // namespace calped
