// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/pyramid.h"

#include "pyramid/placement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <new>

namespace calped {

namespace {

// The computed level at scale 1/2, source of the smaller computed levels (as in the
// toolbox), or -1.
int halfLevelOf(const ModelParams &p, const ScaleList &scales)
{
	for (int i = 0; i < scales.count; i++)
		if (scales.levels[i].computed && scales.levels[i].scale == 0.5 && p.nApprox > 0)
			return i;
	return -1;
}

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Planes of one level's ten channels laid back to back in `base`.
void planesAt(uint16_t *base, int width, int height, Plane<uint16_t> out[kChannelCount])
{
	for (int c = 0; c < kChannelCount; c++)
		out[c] = { base + size_t(c) * width * height, width, height, width };
}

} // namespace

Status Pyramid::init(const ModelParams &params, int maxWidth, int maxHeight,
		     const kernels::KernelTable &k, double upscale)
{
	k_ = &k;
	if (!(upscale >= 1.0 && upscale <= 8.0))
		return Status::error(ErrorCode::InvalidArgument,
				     "pyramid upscale %g is outside [1, 8]", upscale);
	upscale_ = upscale;
	if (params.shrink != 4 || params.nOrients != 6 || params.gradFull != 0 ||
	    params.gradColorChn != 0 || params.pyramidSmooth > 1 || params.colorSmooth > 1 ||
	    params.histBinSize != params.shrink)
		return Status::error(ErrorCode::ModelUnsupported,
				     "calped implements shrink 4, 6 orientations in [0, pi), gradients "
				     "over all colour channels and smoothing radius <= 1");
	// The normalisation's sums are uint32: (r+1)^4 * 65535 + its constant must fit.
	const double weightSum = std::pow(params.gradNormRad + 1.0, 4.0);
	if (params.gradNormRad > 15 ||
	    weightSum * 65535.0 + params.gradNormConst * 65536.0 * weightSum > 4294967295.0)
		return Status::error(ErrorCode::ModelUnsupported,
				     "gradient normalisation radius %d with constant %g exceeds calped's "
				     "32-bit sums (radius <= 15)",
				     int(params.gradNormRad), double(params.gradNormConst));
	// Histograms interpolate between orientations (softBin 0) or not at all (-2); the
	// toolbox's odd values also spread pixels over neighbouring cells.
	if (params.softBin != 0 && params.softBin != -2)
		return Status::error(ErrorCode::ModelUnsupported,
				     "softBin %d: calped implements 0 and -2 (no spatial interpolation)",
				     int(params.softBin));
	params_ = params;
	maxWidth_ = maxWidth;
	maxHeight_ = maxHeight;
	placedCount_ = 0;
	padH_ = params.padH / params.shrink;
	padW_ = params.padW / params.shrink;
	// A band of a level's LUV image gives exact channels in its rows but the margin: the
	// colour smoothing and the gradient each reach one row, the normalisation gradNormRad
	// rows. Rounded up to whole cells.
	channelMargin_ = (params.gradNormRad + 2 + 3) / 4 * 4;

	try {
		kernels::buildLuvTables(luvTables_);
		// The first computed scale is upscale * 2^nOctUp: that image is the largest one
		// processed.
		const double up = upscale * double(1 << params.nOctUp);
		const int luvW = int(std::ceil(maxWidth * up)) + 8, luvH = int(std::ceil(maxHeight * up)) + 8;
		channels_.init(params, luvW, luvH, k);
		for (int c = 0; c < 3; c++) {
			luv_[c].allocate(maxWidth, maxHeight);
			halfLuv_[c].allocate(maxWidth / 2 + 4, maxHeight / 2 + 4);
			levelLuv_[c].allocate(luvW, luvH);
		}
		resampleTmp_.allocate(std::max(luvW, maxWidth), std::max(luvH, maxHeight));
		const size_t taps = size_t(std::max(luvW, luvH)) + 8;
		xTaps_.resize(taps);
		yTaps_.resize(taps);
		yTapsGain_.resize(taps);
		yTapsBand_.resize(taps * kMaxTapSets);

		maxLevelH_ = luvH / 4 + 2;
		maxLevelW_ = luvW / 4 + 2;
		// Computed levels shrink by 2 per octave: 4/3 of the first one's cells in all,
		// plus room for the rounding of every level's size.
		const size_t cells = size_t(maxLevelH_) * maxLevelW_;
		computedStore_.assign(kChannelCount * (cells * 4 / 3 + size_t(kMaxLevels) * (maxLevelH_ + maxLevelW_ + 4)), 0);
		approx_.allocate(maxLevelW_, maxLevelH_ * kChannelCount);
		rowStride_ = maxLevelW_ + 2 * padW_;
		planeStride_ = rowStride_ * (maxLevelH_ + 2 * padH_);
		levelBuf_.assign(size_t(kChannelCount) * planeStride_, 0);
		rowTmp_.assign(size_t(std::max(luvW, luvH)) * 2 + 64, 0);
		buildTapCache(); // without it (a ratio beyond the resampler) compute() reports that
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory,
				     "pyramid buffers for %dx%d frames do not fit in memory",
				     maxWidth, maxHeight);
	}
	return Status::success();
}

bool Pyramid::tapSpec(const ScaleList &scales, int width, int height, int i, int kind, int &n,
		      int &m, double &gain) const
{
	const PyramidLevel &l = scales.levels[i];
	gain = 1.0;
	if (l.computed) {
		const int w1 = l.width * 4, h1 = l.height * 4;
		if ((w1 == width && h1 == height) || kind > kTapsY)
			return false; // the image itself
		const int half = halfLevelOf(params_, scales);
		const bool fromHalf = half >= 0 && i > half;
		const int srcW = fromHalf ? scales.levels[half].width * 4 : width;
		const int srcH = fromHalf ? scales.levels[half].height * 4 : height;
		n = kind == kTapsX ? srcW : srcH;
		m = kind == kTapsX ? w1 : h1;
		return true;
	}
	const PyramidLevel &r = scales.levels[l.source];
	if (kind == kTapsX) {
		n = r.width;
		m = l.width;
		return true;
	}
	// Power law: channel type t scales by (s / s_source)^-lambda_t.
	n = r.height;
	m = l.height;
	gain = std::pow(l.scale / r.scale, -double(params_.lambdas[kind - kTapsY]));
	return true;
}

bool Pyramid::buildTapCache()
{
	tapsCached_ = false;
	ScaleList scales;
	if (!scalesFor(maxWidth_, maxHeight_, scales).ok())
		return true; // no level at this size: nothing to cache
	size_t total = 0;
	for (int i = 0; i < scales.count; i++)
		for (int kind = 0; kind < kTapKinds; kind++) {
			int n, m;
			double gain;
			tapOffset_[i][kind] = kNoTaps;
			if (!tapSpec(scales, maxWidth_, maxHeight_, i, kind, n, m, gain))
				continue;
			tapOffset_[i][kind] = total;
			total += size_t(m);
		}
	tapStore_.assign(total, kernels::ResampleTap());
	for (int i = 0; i < scales.count; i++)
		for (int kind = 0; kind < kTapKinds; kind++) {
			int n, m;
			double gain;
			if (tapOffset_[i][kind] == kNoTaps)
				continue;
			tapSpec(scales, maxWidth_, maxHeight_, i, kind, n, m, gain);
			if (!kernels::buildResampleTaps(n, m, gain, tapStore_.data() + tapOffset_[i][kind]))
				return false;
		}
	tapsCached_ = true;
	return true;
}

const kernels::ResampleTap *Pyramid::levelTaps(int i, int kind)
{
	if (tapsCached_ && width_ == maxWidth_ && height_ == maxHeight_) {
		const size_t at = tapOffset_[i][kind];
		return at == kNoTaps ? nullptr : tapStore_.data() + at;
	}
	int n, m;
	double gain;
	if (!tapSpec(scales_, width_, height_, i, kind, n, m, gain))
		return nullptr;
	kernels::ResampleTap *out = kind == kTapsX ? xTaps_.data() : kind == kTapsY ? yTaps_.data()
										: yTapsGain_.data();
	return kernels::buildResampleTaps(n, m, gain, out) ? out : nullptr;
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
		if (need > computedStore_.size())
			computedStore_.assign(need, 0);
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

void Pyramid::planRows(const CellRange *levelRows, int width, int height)
{
	const int n = scales_.count;
	for (int i = 0; i < n; i++)
		rows_[i] = LevelRows();
	// What the classifier reads, and the raw channel rows the smoothing reaches for;
	// approximated levels pass their needs on to the computed level they resample.
	for (int i = 0; i < n; i++) {
		const PyramidLevel &l = scales_.levels[i];
		LevelRows &r = rows_[i];
		const CellRange wanted = levelRows ? levelRows[i].clipped(l.height) : CellRange{ 0, l.height };
		const CellRange raw = wanted.grown(params_.pyramidSmooth > 0 ? 1 : 0, l.height);
		r.raw.add(raw);
		if (!l.computed && !raw.empty()) {
			// Which source rows the taps read does not depend on their gain.
			const kernels::ResampleTap *taps = levelTaps(i, kTapsY);
			if (taps)
				rows_[l.source].raw.add(sourceRows(taps, raw));
		}
	}
	// The LUV rows each computed level's channels need, with the margin.
	halfLevel_ = halfLevelOf(params_, scales_);
	for (int i = 0; i < n; i++) {
		const PyramidLevel &l = scales_.levels[i];
		if (!l.computed)
			continue;
		LevelRows &r = rows_[i];
		r.chan = CellRange{ 4 * r.raw.begin - channelMargin_, 4 * r.raw.end + channelMargin_ }
				 .clipped(4 * l.height);
		if (r.raw.empty())
			r.chan = CellRange();
		r.luv = r.chan;
	}
	// Sources, smallest first: octaves below the half-size image are resampled from it
	// (as the toolbox does), the others from the whole image.
	fullRows_ = CellRange();
	for (int i = n - 1; i >= 0; i--) {
		const PyramidLevel &l = scales_.levels[i];
		const LevelRows &r = rows_[i];
		if (!l.computed || r.luv.empty())
			continue;
		const int w1 = l.width * 4, h1 = l.height * 4;
		if (w1 == width && h1 == height) {
			fullRows_.add(r.luv);
			continue;
		}
		const bool fromHalf = halfLevel_ >= 0 && i > halfLevel_;
		const kernels::ResampleTap *taps = levelTaps(i, kTapsY);
		if (!taps)
			continue; // computeBands() reports it
		const CellRange src = sourceRows(taps, r.luv);
		if (fromHalf)
			rows_[halfLevel_].luv.add(src);
		else
			fullRows_.add(src);
	}
	// Colour conversion starts on an even row: 4:2:0 strips start on a chroma row.
	if (!fullRows_.empty())
		fullRows_.begin &= ~1;
}

void Pyramid::resampleRows(const Plane<uint16_t> *src, const Plane<uint16_t> *dst, int planes,
			   const kernels::ResampleTap *const *yTaps, const CellRange &rows,
			   const kernels::ResampleTap *xTaps, const CellRange *cols)
{
	// The planes share their source rows (the channel types' gains scale the weights
	// only), so one band of them serves every plane; each distinct yTaps is shifted once.
	CellRange srcRows;
	for (int p = 0; p < planes; p++)
		srcRows.add(sourceRows(yTaps[p], rows));
	const size_t bandTaps = yTapsBand_.size() / kMaxTapSets;
	const kernels::ResampleTap *shiftedFrom[kMaxTapSets] = {};
	int sets = 0;
	kernels::PlaneJob jobs[kChannelCount];
	// Each output column depends only on its own taps, so a range of them is exact.
	const CellRange c = cols ? *cols : CellRange{ 0, dst[0].width };
	for (int p = 0; p < planes; p++) {
		int set = 0;
		while (set < sets && shiftedFrom[set] != yTaps[p])
			set++;
		kernels::ResampleTap *band = yTapsBand_.data() + set * bandTaps;
		if (set == sets) {
			shiftTaps(yTaps[p], rows, srcRows.begin, band);
			shiftedFrom[sets++] = yTaps[p];
		}
		jobs[p] = { src[p].row(srcRows.begin), src[p].stride, dst[p].row(rows.begin) + c.begin,
			    dst[p].stride, band };
	}
	Plane<uint16_t> tmp = resampleTmp_.view(c.size(), srcRows.size());
	k_->resamplePlanes(jobs, planes, src[0].width, srcRows.size(), c.size(), rows.size(),
			   xTaps + c.begin, tmp.data, tmp.stride);
}

Status Pyramid::computeBands(FrameInput &input, const CellRange *levelRows)
{
	const auto t0 = Clock::now();
	const int width = input.width(), height = input.height();
	if (!luv_[0].fits(width, height))
		return Status::error(ErrorCode::ImageTooLarge,
				     "%dx%d is larger than the pyramid was set up for", width, height);
	Status st = scalesFor(width, height, scales_);
	if (!st.ok())
		return st;
	width_ = width;
	height_ = height;
	planRows(levelRows, width, height);
	for (int i = 0; i < scales_.count; i++)
		doneCount_[i] = doneNext_[i] = 0;

	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width, height);
	// Only the rows some level reads.
	const CellRange luvRows = fullRows_;
	fullRows_ = CellRange();
	convertLuvRows(input, luvRows);

	// Computed levels, from the largest: each is resampled from the whole image, or
	// from the half-size image once that exists (as the toolbox does).
	Plane<uint16_t> source[3] = { luv[0], luv[1], luv[2] };
	size_t offset = 0;
	computedCount = 0;
	for (int i = 0; i < scales_.count; i++) {
		const PyramidLevel &l = scales_.levels[i];
		const LevelRows &r = rows_[i];
		if (!l.computed)
			continue;
		// Every computed level keeps its place in the store, so offsets do not depend
		// on which rows a frame needs.
		const size_t need = size_t(kChannelCount) * l.width * l.height;
		if (offset + need > computedStore_.size())
			return Status::error(ErrorCode::ImageTooLarge, "channels of level %d do not fit", i);
		realOffset_[i] = offset;
		offset += need;
		if (r.luv.empty())
			continue;
		const bool isHalf = i == halfLevel_;
		const int w1 = l.width * 4, h1 = l.height * 4;
		Plane<uint16_t> in[3];
		if (w1 == width && h1 == height) {
			for (int c = 0; c < 3; c++)
				in[c] = luv[c];
		} else {
			if (!levelLuv_[0].fits(w1, h1) || (isHalf && !halfLuv_[0].fits(w1, h1)))
				return Status::error(ErrorCode::ImageTooLarge, "level %d does not fit", i);
			const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX);
			const kernels::ResampleTap *yTaps = xTaps ? levelTaps(i, kTapsY) : nullptr;
			if (!yTaps)
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			const kernels::ResampleTap *yTapsOf[3] = { yTaps, yTaps, yTaps };
			for (int c = 0; c < 3; c++)
				in[c] = isHalf ? halfLuv_[c].view(w1, h1) : levelLuv_[c].view(w1, h1);
			resampleRows(source, in, 3, yTapsOf, r.luv, xTaps);
			if (isHalf)
				for (int c = 0; c < 3; c++)
					source[c] = in[c];
		}
		if (r.chan.empty())
			continue;
		Plane<const uint16_t> band[3];
		for (int c = 0; c < 3; c++)
			band[c] = { in[c].row(r.chan.begin), w1, r.chan.size(), in[c].stride };
		Plane<uint16_t> out[kChannelCount];
		planesAt(computedStore_.data() + offset - need, l.width, l.height, out);
		for (int c = 0; c < kChannelCount; c++)
			out[c].data = out[c].row(r.chan.begin / 4);
		channels_.compute(band, w1, r.chan.size(), out);
		computedCount++;
	}
	msChannels = msSince(t0);
	msApprox = 0;
	msSmooth = 0;
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

LevelChannels Pyramid::prepare(int i, const LevelRect *rects, int count)
{
	if (!rects)
		return prepareRect(i, nullptr, nullptr);
	// Rectangles of one level share its buffer: each call fills its own part.
	LevelChannels out;
	for (int k = 0; k < count; k++)
		out = prepareRect(i, &rects[k].rows, &rects[k].cols);
	return out;
}

bool Pyramid::rectsComputable(int width, int height) const
{
	ScaleList scales;
	return scalesFor(width, height, scales).ok() && halfLevelOf(params_, scales) < 0;
}

Status Pyramid::levelColour(FrameInput &input, int i, const CellRange &chan, const CellRange &chanCols,
			   Plane<uint16_t> in[3])
{
	const PyramidLevel &l = scales_.levels[i];
	const int w1 = l.width * 4, h1 = l.height * 4;
	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width_, height_);
	if (w1 == width_ && h1 == height_) {
		convertLuvRows(input, chan);
		for (int c = 0; c < 3; c++)
			in[c] = luv[c];
		return Status::success();
	}
	const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX);
	const kernels::ResampleTap *yTaps = xTaps ? levelTaps(i, kTapsY) : nullptr;
	if (!yTaps)
		return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
	// The level's colour image is shared by the computed levels: resample these rows
	// again from the whole image.
	convertLuvRows(input, sourceRows(yTaps, chan));
	for (int c = 0; c < 3; c++)
		in[c] = levelLuv_[c].view(w1, h1);
	const kernels::ResampleTap *yTapsOf[3] = { yTaps, yTaps, yTaps };
	resampleRows(luv, in, 3, yTapsOf, chan, xTaps, &chanCols);
	return Status::success();
}

Status Pyramid::computeRects(FrameInput &input, const int *levels, const LevelRect *rects, int count)
{
	const int reach = params_.pyramidSmooth > 0 ? 1 : 0;
	// What each computed level must hold: the raw rectangles of its own level and the
	// source rectangles of the levels approximated from it, merged. Merged rectangles
	// stay at least a cell margin apart, so their channels' margins do not overlap much.
	const int gap = 2 * channelMargin_ / 4;
	for (int i = 0; i < scales_.count; i++)
		needCount_[i] = 0;
	for (int k = 0; k < count; k++) {
		const int i = levels[k];
		const PyramidLevel &l = scales_.levels[i];
		LevelRect raw{ rects[k].rows.clipped(l.height).grown(reach, l.height),
			       rects[k].cols.clipped(l.width).grown(reach, l.width) };
		if (raw.empty())
			continue;
		// prepare() checks its rows against these.
		rows_[i].raw.add(raw.rows);
		if (!l.computed) {
			const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX);
			if (!xTaps)
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			const CellRange cols = sourceRows(xTaps, raw.cols);
			const kernels::ResampleTap *yTaps = levelTaps(i, kTapsY);
			if (!yTaps)
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			raw = LevelRect{ sourceRows(yTaps, raw.rows), cols };
		}
		const int c = l.source;
		addMerged(needRects_[c], needCount_[c], kMaxRects, raw, gap);
	}
	const auto t0 = Clock::now();
	for (int i = 0; i < scales_.count; i++)
		for (int k = 0; k < needCount_[i]; k++) {
			const LevelRect &r = needRects_[i][k];
			bool done = false;
			for (int d = 0; d < doneCount_[i] && !done; d++)
				done = doneRects_[i][d].contains(r);
			if (done)
				continue;
			const Status st = computeRect(input, i, r);
			if (!st.ok())
				return st;
		}
	msChannels += msSince(t0);
	return Status::success();
}

Status Pyramid::computeRect(FrameInput &input, int i, const LevelRect &r)
{
	const PyramidLevel &l = scales_.levels[i];
	const int w1 = l.width * 4, h1 = l.height * 4;
	// The colour pixels with the channels' margin on every side (whole cells), computed
	// into the approximation buffer (free between levels); only r is kept.
	const CellRange chan = CellRange{ 4 * r.rows.begin - channelMargin_, 4 * r.rows.end + channelMargin_ }
				     .clipped(h1);
	const CellRange chanCols = CellRange{ 4 * r.cols.begin - channelMargin_, 4 * r.cols.end + channelMargin_ }
					 .clipped(w1);
	Plane<uint16_t> in[3];
	const Status st = levelColour(input, i, chan, chanCols, in);
	if (!st.ok())
		return st;
	Plane<uint16_t> scratch[kChannelCount];
	planesAt(approx_.data(), chanCols.size() / 4, chan.size() / 4, scratch);
	Plane<const uint16_t> block[3];
	for (int c = 0; c < 3; c++)
		block[c] = { in[c].row(chan.begin) + chanCols.begin, chanCols.size(), chan.size(), in[c].stride };
	channels_.compute(block, chanCols.size(), chan.size(), scratch);
	Plane<uint16_t> out[kChannelCount];
	realLevelPlanes(i, out);
	const int dy = chan.begin / 4, dx = chanCols.begin / 4;
	for (int c = 0; c < kChannelCount; c++)
		for (int y = r.rows.begin; y < r.rows.end; y++)
			std::memcpy(out[c].row(y) + r.cols.begin, scratch[c].row(y - dy) + (r.cols.begin - dx),
				    sizeof(uint16_t) * r.cols.size());
	// Remember it (the oldest is forgotten when the list is full: computed again if
	// asked for again).
	if (doneCount_[i] == 0 && rows_[i].chan.empty())
		computedCount++;
	if (doneCount_[i] < kMaxRects) {
		doneRects_[i][doneCount_[i]++] = r;
	} else {
		doneRects_[i][doneNext_[i]] = r;
		doneNext_[i] = (doneNext_[i] + 1) % kMaxRects;
	}
	rectsComputed++;
	return Status::success();
}

void Pyramid::convertLuvRows(FrameInput &input, CellRange rows)
{
	rows = rows.clipped(height_);
	if (rows.empty() || fullRows_.contains(rows))
		return;
	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width_, height_);
	// The rows above and below those converted, a strip of RGB rows at a time (the
	// whole band at once when the frame is RGB8 already); strips start on even rows
	// (4:2:0 chroma).
	const CellRange parts[2] = { fullRows_.empty() ? rows : CellRange{ rows.begin, fullRows_.begin },
				   fullRows_.empty() ? CellRange() : CellRange{ fullRows_.end, rows.end } };
	const int strip = input.stripRows();
	for (const CellRange &part : parts) {
		if (part.empty())
			continue;
		for (int y0 = part.begin & ~1; y0 < part.end; y0 += strip) {
			const int n = std::min(strip, part.end - y0);
			ptrdiff_t stride;
			const uint8_t *rgb = input.rows(y0, n, stride);
			k_->rgbToLuv(luvTables_, rgb, stride, width_, n, luv[0].row(y0), luv[1].row(y0),
				     luv[2].row(y0), luv[0].stride);
		}
	}
	fullRows_.add(rows);
}

void Pyramid::realLevelPlanes(int i, Plane<uint16_t> out[kChannelCount])
{
	const PyramidLevel &l = scales_.levels[i];
	planesAt(computedStore_.data() + realOffset_[i], l.width, l.height, out);
}

void Pyramid::approximate(int i, const CellRange &rows, const CellRange &cols,
			  Plane<uint16_t> out[kChannelCount])
{
	const PyramidLevel &l = scales_.levels[i];
	Plane<uint16_t> src[kChannelCount];
	realLevelPlanes(l.source, src);
	planesAt(approx_.data(), l.width, l.height, out);
	const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX);
	// Channel types: colour, magnitude, orientations; each has its power-law gain.
	const int typeOf[kChannelCount] = { 0, 0, 0, 1, 2, 2, 2, 2, 2, 2 };
	const kernels::ResampleTap *yTaps[kChannelCount];
	for (int c = 0; c < kChannelCount; c++) {
		yTaps[c] = c > 0 && typeOf[c] == typeOf[c - 1] ? yTaps[c - 1] : levelTaps(i, kTapsY + typeOf[c]);
		if (!yTaps[c])
			return;
	}
	if (xTaps)
		resampleRows(src, out, kChannelCount, yTaps, rows, xTaps, &cols);
}

LevelChannels Pyramid::prepareRect(int i, const CellRange *only, const CellRange *onlyCols)
{
	const PyramidLevel &l = scales_.levels[i];
	const int reach = params_.pyramidSmooth > 0 ? 1 : 0;
	// Smoothing the raw band is exact in the wanted rows (it reaches one row further);
	// padding above or below the level exists only where the band touches that edge.
	CellRange band = rows_[i].raw;
	if (only) {
		const CellRange wanted = *only;
		band = wanted.grown(reach, l.height);
		if (!rows_[i].raw.contains(band))
			band = rows_[i].raw; // outside what was computed: keep its band
	}
	// The same across: columns one wider than those wanted (the smoothing treats the ends
	// of the range as the level's edges, so only the wanted columns are exact), padding
	// beside the level only where the range touches that side.
	const CellRange cols = onlyCols ? onlyCols->grown(reach, l.width) : CellRange{ 0, l.width };
	Plane<uint16_t> raw[kChannelCount];
	if (l.computed) {
		realLevelPlanes(i, raw);
	} else {
		const auto t0 = Clock::now();
		approximate(i, band, cols, raw);
		msApprox += msSince(t0);
	}

	const auto t0 = Clock::now();
	const int w = l.width, h = l.height;
	const int pw = w + 2 * padW_, ph = h + 2 * padH_;
	for (int c = 0; c < kChannelCount; c++) {
		uint16_t *plane = levelBuf_.data() + c * planeStride_;
		uint16_t *inner = plane + padH_ * rowStride_ + padW_;
		if (band.empty() || cols.empty())
			break;
		if (params_.pyramidSmooth > 0)
			k_->smoothTri1(raw[c].row(band.begin) + cols.begin, raw[c].stride,
				       inner + band.begin * rowStride_ + cols.begin, rowStride_,
				       cols.size(), band.size(), rowTmp_.data());
		else
			for (int y = band.begin; y < band.end; y++)
				std::memcpy(inner + y * rowStride_ + cols.begin, raw[c].row(y) + cols.begin,
					    sizeof(uint16_t) * cols.size());
		// Colour is padded by replication, gradients by zeros (the toolbox's padWith).
		const bool replicate = c < 3;
		for (int y = padH_ + band.begin; y < padH_ + band.end; y++) {
			uint16_t *row = plane + y * rowStride_;
			if (cols.begin == 0)
				std::fill(row, row + padW_, replicate ? row[padW_] : uint16_t(0));
			if (cols.end == w)
				std::fill(row + padW_ + w, row + pw, replicate ? row[padW_ + w - 1] : uint16_t(0));
		}
		for (int y = 0; y < padH_; y++) {
			uint16_t *top = plane + y * rowStride_;
			uint16_t *bottom = plane + (ph - 1 - y) * rowStride_;
			if (band.begin == 0) {
				if (replicate)
					std::memcpy(top, plane + padH_ * rowStride_, sizeof(uint16_t) * pw);
				else
					std::fill(top, top + pw, 0);
			}
			if (band.end == h) {
				if (replicate)
					std::memcpy(bottom, plane + (padH_ + h - 1) * rowStride_,
						    sizeof(uint16_t) * pw);
				else
					std::fill(bottom, bottom + pw, 0);
			}
		}
	}
	msSmooth += msSince(t0);

	LevelChannels out;
	out.data = levelBuf_.data();
	out.paddedHeight = ph;
	out.paddedWidth = pw;
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	return out;
}

} // namespace calped
