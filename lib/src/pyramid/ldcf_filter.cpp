// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/ldcf_filter.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace calped {

namespace {

// imResample(C, .5): round(n / 2) samples, Matlab's rounding (halves away from zero).
int halfSize(int n) { return (n + 1) / 2; }

// The outputs whose taps lie inside `src` (taps move forward with the output, so they
// are one run).
CellRange outputsInside(const kernels::ResampleTap *taps, int m, const CellRange &src)
{
	CellRange out{ m, m };
	for (int o = 0; o < m; o++)
		if (taps[o].first >= src.begin && taps[o].first + taps[o].count <= src.end) {
			if (out.begin == m)
				out.begin = o;
			out.end = o + 1;
		}
	return out.empty() ? CellRange{} : out;
}

// Valid input [begin, end) of an n-sample axis: the filter output is exact where its
// reach stays inside, or meets the plane's own edge (zero beyond it, as conv2 'same').
CellRange exactFiltered(const CellRange &valid, int n, int reach)
{
	return CellRange{ valid.begin > 0 ? valid.begin + reach : 0,
			  valid.end < n ? valid.end - reach : n };
}

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
		yShifted_.resize(size_t(halfSize(maxHeight)) + 1);
		xShifted_.resize(size_t(halfSize(maxWidth)) + 1);
		rowStride_ = halfSize(maxWidth);
		planeStride_ = rowStride_ * halfSize(maxHeight);
		out_.assign(size_t(planeStride_) * kChannelCount * nFilters_, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "LDCF buffers for %dx%d levels", maxWidth,
				     maxHeight);
	}
	return Status::success();
}

uint64_t LdcfFilter::bytesFor(int nFilters, uint64_t maxHeight, uint64_t maxWidth)
{
	// As init() sizes them: the filtered level and the row pass (uint16), the half-size
	// output planes, and four tap arrays.
	const uint64_t halfH = (maxHeight + 1) / 2, halfW = (maxWidth + 1) / 2;
	const uint64_t planes = maxHeight * maxWidth + halfW * maxHeight +
				halfH * halfW * uint64_t(kChannelCount) * uint64_t(nFilters);
	return 2 * planes + (2 * halfW + 2 * halfH + 4) * sizeof(kernels::ResampleTap);
}

LevelChannels LdcfFilter::apply(const LevelChannels &level, const LevelRect *rects, int count,
				int padH, int padW)
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
	if (!rects) {
		applyRect(level, CellRange{ 0, h }, CellRange{ 0, w });
	} else {
		// Before padding the level is (h - 2 padH) x (w - 2 padW); a rectangle touching
		// its edge has the padding beyond it too (Pyramid::prepare pads there).
		const int lh = h - 2 * padH, lw = w - 2 * padW;
		for (int k = 0; k < count; k++) {
			const LevelRect &r = rects[k];
			if (r.empty())
				continue;
			const CellRange rows{ r.rows.begin <= 0 ? 0 : r.rows.begin + padH,
					      r.rows.end >= lh ? h : r.rows.end + padH };
			const CellRange cols{ r.cols.begin <= 0 ? 0 : r.cols.begin + padW,
					      r.cols.end >= lw ? w : r.cols.end + padW };
			applyRect(level, rows, cols);
		}
	}
	out.data = out_.data();
	out.paddedHeight = mh;
	out.paddedWidth = mw;
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	return out;
}

void LdcfFilter::applyRect(const LevelChannels &level, const CellRange &rows, const CellRange &cols)
{
	const int h = level.paddedHeight, w = level.paddedWidth;
	const int mh = halfSize(h), mw = halfSize(w);
	const int reach = size_ / 2;
	// The outputs computable from this rectangle alone, the filtered cells they read, and
	// the input those need (conv2 'same' is zero beyond the plane, and so beyond the
	// window the kernel is given: only the filtered cells `reach` inside it are exact).
	const CellRange outRows = outputsInside(yTaps_.data(), mh, exactFiltered(rows, h, reach));
	const CellRange outCols = outputsInside(xTaps_.data(), mw, exactFiltered(cols, w, reach));
	if (outRows.empty() || outCols.empty())
		return;
	const CellRange srcRows = sourceRows(yTaps_.data(), outRows);
	const CellRange srcCols = sourceRows(xTaps_.data(), outCols);
	const CellRange inRows = srcRows.grown(reach, h).intersected(rows);
	const CellRange inCols = srcCols.grown(reach, w).intersected(cols);
	// The resampler sees only the source rectangle (so exact halving keeps its fast path).
	shiftTaps(yTaps_.data(), outRows, srcRows.begin, yShifted_.data());
	shiftTaps(xTaps_.data(), outCols, srcCols.begin, xShifted_.data());
	const Plane<uint16_t> full = full_.view(w, h);
	const int taps = size_ * size_;
	for (int j = 0; j < nFilters_; j++)
		for (int c = 0; c < kChannelCount; c++) {
			const int plane = j * kChannelCount + c;
			k_->ldcfFilter(level.data + c * level.planeStride + inRows.begin * level.rowStride +
					       inCols.begin,
				       level.rowStride, inCols.size(), inRows.size(),
				       filters_.data() + size_t(plane) * taps, size_,
				       full.row(inRows.begin) + inCols.begin, full.stride);
			k_->resamplePlane(full.row(srcRows.begin) + srcCols.begin, full.stride,
					  srcCols.size(), srcRows.size(),
					  out_.data() + plane * planeStride_ + outRows.begin * rowStride_ +
						  outCols.begin,
					  rowStride_, outCols.size(), outRows.size(), xShifted_.data(),
					  yShifted_.data(), tmp_.data(), outCols.size());
		}
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
