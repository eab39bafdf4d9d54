// SPDX-License-Identifier: BSD-2-Clause
// Pyramid setup (buffers, level layout, placed levels) and its per-frame entry points.
#include "pyramid/pyramid.h"
#include "pyramid/pyramid_util.h"
#include "pyramid/placement.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace calped {

using namespace pyramid_util;

Status Pyramid::allocateScratch(Scratch &s, int luvW, int luvH, int maxWidth)
{
	s.channels.init(params_, luvW, luvH, *k_);
	for (int c = 0; c < 3; c++)
		s.levelLuv[c].allocate(luvW, luvH);
	s.resampleTmp.allocate(std::max(luvW, maxWidth_), std::max(luvH, maxHeight_));
	const size_t taps = size_t(std::max(luvW, luvH)) + 8;
	for (auto &kind : s.taps)
		kind.resize(taps);
	s.yTapsBand.resize(taps * kMaxTapSets);
	s.approx.allocate(maxLevelW_, maxLevelH_ * kChannelCount);
	s.levelBuf.allocate(int(planeStride_), kChannelCount);
	s.strip.allocate(maxWidth * 3, FrameInput::kStripRows);
	s.rowTmp.assign(size_t(std::max(luvW, luvH)) * 2 + 64, 0);
	return Status::success();
}

double Pyramid::msApprox() const
{
	double ms = 0;
	for (const auto &s : scratch_)
		ms += s->msApprox;
	return ms;
}

double Pyramid::msSmooth() const
{
	double ms = 0;
	for (const auto &s : scratch_)
		ms += s->msSmooth;
	return ms;
}

double Pyramid::msFilter() const
{
	double ms = 0;
	for (const auto &s : scratch_)
		ms += s->msFilter;
	return ms;
}

Status Pyramid::setFilters(const Model &model)
{
	filtered_ = false;
	// The largest prepared level: the first computed one, padded.
	const int h = maxLevelH_ + 2 * padH_, w = maxLevelW_ + 2 * padW_;
	for (auto &s : scratch_) {
		const Status st = s->filter.init(model, h, w, *k_);
		if (!st.ok())
			return st;
	}
	filtered_ = true;
	return Status::success();
}

ptrdiff_t Pyramid::classifierRowStride() const
{
	return filtered_ ? scratch_[0]->filter.rowStride() : rowStride_;
}

ptrdiff_t Pyramid::classifierPlaneStride() const
{
	return filtered_ ? scratch_[0]->filter.planeStride() : planeStride_;
}

LevelChannels Pyramid::classifierLevel(int i, const LevelRect *rects, int count, int worker)
{
	const LevelChannels level = prepare(i, rects, count, worker);
	if (!filtered_)
		return level;
	Scratch &s = *scratch_[size_t(worker)];
	const auto t0 = StageClock::now();
	// Rectangles' windows (the calibrated method's) read a few percent of the filtered
	// cells: computed as read. A whole level's windows read most of them: filtered at once
	// (faster there, docs/calibrated.md).
	const LevelChannels out = rects ? s.filter.onDemand(level) : s.filter.apply(level);
	s.msFilter += msSince(t0);
	return out;
}

Status Pyramid::init(const ModelParams &params, int maxWidth, int maxHeight,
		     const kernels::KernelTable &k, double upscale, ThreadPool *pool)
{
	k_ = &k;
	pool_ = pool;
	if (!(upscale >= 1.0 && upscale <= 8.0))
		return Status::error(ErrorCode::InvalidArgument,
				     "pyramid upscale %g is outside [1, 8]", upscale);
	upscale_ = upscale;
	// LDCF's filters (params.nFilters) apply after the pyramid (pyramid/ldcf_filter.h).
	if ((params.shrink != 4 && params.shrink != 2) || params.nOrients != 6 ||
	    params.gradFull != 0 || params.gradColorChn != 0 || params.pyramidSmooth > 1 ||
	    params.colorSmooth > 1 || params.histBinSize != params.shrink)
		return Status::error(ErrorCode::ModelUnsupported,
				     "calped implements shrink 4 and 2, 6 orientations in [0, pi), "
				     "gradients over all colour channels and smoothing radius <= 1");
	// The normalisation's sums are uint32: (r+1)^4 * 65535 + its constant must fit.
	const double weightSum = std::pow(params.gradNormRad + 1.0, 4.0);
	if (params.gradNormRad > 15 ||
	    weightSum * 65535.0 + params.gradNormConst * 65536.0 * weightSum > 4294967295.0)
		return Status::error(ErrorCode::ModelUnsupported,
				     "gradient normalisation radius %d with constant %g exceeds calped's "
				     "32-bit sums (radius <= 15)",
				     int(params.gradNormRad), double(params.gradNormConst));
	// Histograms interpolate between orientations (softBin 0) or not at all (-2); the
	// toolbox's odd values also spread pixels over neighbouring cells, which calped
	// implements for 2x2 cells (Caltech+: softBin 1).
	if (params.softBin % 2 != 0 && params.shrink != 2)
		return Status::error(ErrorCode::ModelUnsupported,
				     "softBin %d (spatial interpolation) is implemented for shrink 2 only",
				     int(params.softBin));
	params_ = params;
	filtered_ = false; // the scratch sets (and their filters) are made anew below
	maxWidth_ = maxWidth;
	maxHeight_ = maxHeight;
	placedCount_ = 0;
	padH_ = params.padH / params.shrink;
	padW_ = params.padW / params.shrink;
	// A band of a level's LUV image gives exact channels in its rows but the margin: the
	// colour smoothing and the gradient each reach one row, the normalisation gradNormRad
	// rows. Rounded up to whole cells.
	const int s = params.shrink; // pixels per cell
	channelMargin_ = (params.gradNormRad + 2 + s - 1) / s * s;

	try {
		kernels::buildLuvTables(luvTables_, params.toolboxCpu == ToolboxCpu::AmdEpyc
							    ? kernels::RcpRule::AmdEpyc
							    : kernels::RcpRule::Intel);
		// The first computed scale is upscale * 2^nOctUp: that image is the largest one
		// processed.
		const double up = upscale * double(1 << params.nOctUp);
		const int luvW = int(std::ceil(maxWidth * up)) + 8, luvH = int(std::ceil(maxHeight * up)) + 8;
		for (int c = 0; c < 3; c++) {
			luv_[c].allocate(maxWidth, maxHeight);
			halfLuv_[c].allocate(maxWidth / 2 + 4, maxHeight / 2 + 4);
		}

		maxLevelH_ = luvH / s + 2;
		maxLevelW_ = luvW / s + 2;
		// Computed levels shrink by 2 per octave: 4/3 of the first one's cells in all,
		// plus room for the rounding of every level's size.
		const size_t cells = size_t(maxLevelH_) * maxLevelW_;
		computedStore_.allocate(int(kChannelCount * (cells * 4 / 3 + size_t(kMaxLevels) * (maxLevelH_ + maxLevelW_ + 4))), 1);
		rowStride_ = maxLevelW_ + 2 * padW_;
		planeStride_ = rowStride_ * (maxLevelH_ + 2 * padH_);
		// One scratch set per thread; untouched pages of the others cost no memory.
		const int threads = pool ? pool->size() : 1;
		scratch_.clear();
		for (int w = 0; w < threads; w++) {
			scratch_.push_back(std::make_unique<Scratch>());
			allocateScratch(*scratch_.back(), luvW, luvH, maxWidth);
		}
		if (!buildTapCache())
			return Status::error(ErrorCode::InvalidArgument,
					     "%dx%d frames need a pyramid level resampled more than 10x "
					     "smaller in one step, beyond the resampler",
					     maxWidth, maxHeight);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory,
				     "pyramid buffers for %dx%d frames do not fit in memory",
				     maxWidth, maxHeight);
	}
	return Status::success();
}

Status Pyramid::scalesFor(int width, int height, ScaleList &out) const
{
	if (!computeScales(params_, height, width, out, upscale_))
		return Status::error(ErrorCode::InvalidArgument, "too many pyramid levels");
	if (out.count == 0)
		return Status::error(ErrorCode::ImageTooSmall,
				     "%dx%d is smaller than the model's minimum %gx%g", width, height,
				     double(params_.minDsW), double(params_.minDsH));
	if (placedCount_ > 0 && width == maxWidth_ && height == maxHeight_ && out.count == placedCount_)
		applyPlacedLevels(out, placedSource_);
	return Status::success();
}

Status Pyramid::placeLevels(const int *source, int count)
{
	placedCount_ = 0;
	ScaleList scales;
	Status st = scalesFor(maxWidth_, maxHeight_, scales);
	if (!st.ok())
		return st;
	if (count != scales.count)
		return Status::error(ErrorCode::InvalidArgument,
				     "placement for %d levels, the pyramid has %d", count, scales.count);
	for (int i = 0; i < count; i++) {
		const int s = source[i];
		if (s < 0 || s >= count || source[s] != s)
			return Status::error(ErrorCode::InvalidArgument,
					     "level %d is approximated from level %d, which is not computed",
					     i, s);
	}
	applyPlacedLevels(scales, source);
	// The channel store holds every computed level, each in its place.
	size_t need = 0;
	for (int i = 0; i < count; i++)
		if (scales.levels[i].computed)
			need += size_t(kChannelCount) * scales.levels[i].width * scales.levels[i].height;
	try {
		if (need > computedStore_.capacity())
			computedStore_.allocate(int(need), 1);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "channels of the placed levels");
	}
	std::copy(source, source + count, placedSource_);
	placedCount_ = count;
	try {
		if (!buildTapCache()) {
			placedCount_ = 0;
			buildTapCache();
			return Status::error(ErrorCode::InvalidArgument,
					     "a placed level is too small to be resampled from the image");
		}
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "resampling taps of the placed levels");
	}
	return Status::success();
}

Status Pyramid::compute(FrameInput &input, const PyramidDemand &demand)
{
	const bool first = frameDemands_++ == 0;
	if (demand.everything)
		return first ? computeBands(input, nullptr)
			     : Status::error(ErrorCode::InvalidArgument,
					     "the whole frame must be the frame's first demand");
	if (first) {
		// Nothing computed yet; then the rectangles, where the levels allow.
		for (int i = 0; i < kMaxLevels; i++)
			demandBands_[i] = CellRange();
		const Status st = computeBands(input, demandBands_);
		if (!st.ok() || halfLevel_ < 0)
			return st.ok() ? computeRects(input, demand.levels, demand.rects, demand.count) : st;
		// A half-size source: full-width bands of the demanded rows.
		for (int k = 0; k < demand.count; k++)
			demandBands_[demand.levels[k]].add(demand.rects[k].rows);
		return computeBands(input, demandBands_);
	}
	if (halfLevel_ < 0)
		return computeRects(input, demand.levels, demand.rects, demand.count);
	for (int k = 0; k < demand.count; k++)
		if (!demandBands_[demand.levels[k]].contains(demand.rects[k].rows))
			return Status::error(ErrorCode::InvalidArgument,
					     "level %d rows %d..%d: outside the frame's first demand, and "
					     "this pyramid (a half-size source) cannot extend it",
					     demand.levels[k], demand.rects[k].rows.begin,
					     demand.rects[k].rows.end);
	return Status::success();
}

LevelChannels Pyramid::prepare(int i, const LevelRect *rects, int count, int worker)
{
	Scratch &s = *scratch_[size_t(worker)];
	if (!rects)
		return prepareRect(i, nullptr, nullptr, s);
	// Rectangles of one level share its buffer: each call fills its own part.
	LevelChannels out;
	for (int k = 0; k < count; k++)
		out = prepareRect(i, &rects[k].rows, &rects[k].cols, s);
	return out;
}

bool Pyramid::rectsComputable(int width, int height) const
{
	ScaleList scales;
	return scalesFor(width, height, scales).ok() && halfLevelOf(params_, scales) < 0;
}

} // namespace calped
