// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/pyramid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <new>

namespace calped {

namespace {

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
		     const kernels::KernelTable &k)
{
	k_ = &k;
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
	padH_ = params.padH / params.shrink;
	padW_ = params.padW / params.shrink;

	try {
		kernels::buildLuvTables(luvTables_);
		// The first computed scale is 2^nOctUp: that image is the largest one processed.
		const int up = 1 << params.nOctUp;
		const int luvW = maxWidth * up + 8, luvH = maxHeight * up + 8;
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

		maxLevelH_ = luvH / 4 + 2;
		maxLevelW_ = luvW / 4 + 2;
		// Computed levels shrink by 2 per octave: 4/3 of the first one's cells in all,
		// plus room for the rounding of every level's size.
		const size_t cells = size_t(maxLevelH_) * maxLevelW_;
		realStore_.assign(kChannelCount * (cells * 4 / 3 + size_t(kMaxLevels) * (maxLevelH_ + maxLevelW_ + 4)), 0);
		approx_.allocate(maxLevelW_, maxLevelH_ * kChannelCount);
		rowStride_ = maxLevelW_ + 2 * padW_;
		planeStride_ = rowStride_ * (maxLevelH_ + 2 * padH_);
		levelBuf_.assign(size_t(kChannelCount) * planeStride_, 0);
		rowTmp_.assign(size_t(std::max(luvW, luvH)) * 2 + 64, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory,
				     "pyramid buffers for %dx%d frames do not fit in memory",
				     maxWidth, maxHeight);
	}
	return Status::success();
}

Status Pyramid::scalesFor(int width, int height, ScaleList &out) const
{
	if (!computeScales(params_, height, width, out))
		return Status::error(ErrorCode::InvalidArgument, "too many pyramid levels");
	if (out.count == 0)
		return Status::error(ErrorCode::ImageTooSmall,
				     "%dx%d is smaller than the model's minimum %gx%g", width, height,
				     double(params_.minDsW), double(params_.minDsH));
	return Status::success();
}

Status Pyramid::build(FrameInput &input, const bool *levelNeeded)
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
	// Computed levels whose channels some needed level uses, and the last one needed
	// (the half-size image must exist for every octave below it).
	bool channelsNeeded[kMaxLevels];
	int lastNeeded = -1;
	for (int i = 0; i < scales_.count; i++)
		channelsNeeded[i] = false;
	for (int i = 0; i < scales_.count; i++)
		if (!levelNeeded || levelNeeded[i]) {
			channelsNeeded[scales_.levels[i].source] = true;
			lastNeeded = std::max(lastNeeded, scales_.levels[i].source);
		}
	height_ = height;

	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width, height);
	// A strip of RGB rows at a time (the whole frame at once when it is RGB8 already).
	const int strip = input.stripRows();
	for (int y0 = 0; y0 < height; y0 += strip) {
		const int rows = std::min(strip, height - y0);
		ptrdiff_t stride;
		const uint8_t *rgb = input.rows(y0, rows, stride);
		k_->rgbToLuv(luvTables_, rgb, stride, width, rows, luv[0].row(y0), luv[1].row(y0),
			     luv[2].row(y0), luv[0].stride);
	}

	// Computed levels, from the largest: each is resampled from the whole image, or
	// from the half-size image once that exists (as the toolbox does).
	Plane<uint16_t> source[3] = { luv[0], luv[1], luv[2] };
	size_t offset = 0;
	computedCount = 0;
	for (int i = 0; i < scales_.count; i++) {
		const PyramidLevel &l = scales_.levels[i];
		if (!l.computed || i > lastNeeded)
			continue;
		const bool isHalf = l.scale == 0.5 && params_.nApprox > 0;
		// A computed level nobody needs is skipped, unless it is the half-size image
		// the smaller octaves are resampled from.
		if (!channelsNeeded[i] && !isHalf)
			continue;
		const int w1 = l.width * 4, h1 = l.height * 4;
		Plane<const uint16_t> in[3];
		if (w1 == width && h1 == height) {
			for (int c = 0; c < 3; c++)
				in[c] = { luv[c].data, w1, h1, luv[c].stride };
		} else {
			if (!levelLuv_[0].fits(w1, h1) || (isHalf && !halfLuv_[0].fits(w1, h1)))
				return Status::error(ErrorCode::ImageTooLarge, "level %d does not fit", i);
			if (!kernels::buildResampleTaps(source[0].width, w1, 1.0, xTaps_.data()) ||
			    !kernels::buildResampleTaps(source[0].height, h1, 1.0, yTaps_.data()))
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			Plane<uint16_t> tmp = resampleTmp_.view(w1, source[0].height);
			Plane<uint16_t> dst[3];
			for (int c = 0; c < 3; c++) {
				dst[c] = isHalf ? halfLuv_[c].view(w1, h1) : levelLuv_[c].view(w1, h1);
				k_->resamplePlane(source[c].data, source[c].stride, source[c].width,
							   source[c].height, dst[c].data, dst[c].stride,
							   w1, h1, xTaps_.data(), yTaps_.data(), tmp.data,
							   tmp.stride);
				in[c] = { dst[c].data, w1, h1, dst[c].stride };
			}
			if (isHalf)
				for (int c = 0; c < 3; c++)
					source[c] = dst[c];
		}
		if (!channelsNeeded[i])
			continue;
		const size_t need = size_t(kChannelCount) * l.width * l.height;
		if (offset + need > realStore_.size())
			return Status::error(ErrorCode::ImageTooLarge, "channels of level %d do not fit", i);
		realOffset_[i] = offset;
		Plane<uint16_t> out[kChannelCount];
		planesAt(realStore_.data() + offset, l.width, l.height, out);
		channels_.compute(in, w1, h1, out);
		offset += need;
		computedCount++;
	}
	msChannels = msSince(t0);
	msApprox = 0;
	msSmooth = 0;
	return Status::success();
}

void Pyramid::realLevelPlanes(int i, Plane<uint16_t> out[kChannelCount])
{
	const PyramidLevel &l = scales_.levels[i];
	planesAt(realStore_.data() + realOffset_[i], l.width, l.height, out);
}

void Pyramid::approximate(int i, Plane<uint16_t> out[kChannelCount])
{
	const PyramidLevel &l = scales_.levels[i];
	const PyramidLevel &r = scales_.levels[l.source];
	Plane<uint16_t> src[kChannelCount];
	realLevelPlanes(l.source, src);
	planesAt(approx_.data(), l.width, l.height, out);
	kernels::buildResampleTaps(r.width, l.width, 1.0, xTaps_.data());
	Plane<uint16_t> tmp = resampleTmp_.view(l.width, r.height);
	// Power law: channel type j scales by (s / s_source)^-lambda_j.
	const int typeOf[kChannelCount] = { 0, 0, 0, 1, 2, 2, 2, 2, 2, 2 };
	int builtFor = -1;
	for (int c = 0; c < kChannelCount; c++) {
		const int type = typeOf[c];
		if (type != builtFor) {
			const double gain = std::pow(l.scale / r.scale, -double(params_.lambdas[type]));
			kernels::buildResampleTaps(r.height, l.height, gain, yTapsGain_.data());
			builtFor = type;
		}
		k_->resamplePlane(src[c].data, src[c].stride, r.width, r.height, out[c].data,
					   out[c].stride, l.width, l.height, xTaps_.data(),
					   yTapsGain_.data(), tmp.data, tmp.stride);
	}
}

LevelChannels Pyramid::level(int i)
{
	const PyramidLevel &l = scales_.levels[i];
	Plane<uint16_t> raw[kChannelCount];
	if (l.computed) {
		realLevelPlanes(i, raw);
	} else {
		const auto t0 = Clock::now();
		approximate(i, raw);
		msApprox += msSince(t0);
	}

	const auto t0 = Clock::now();
	const int w = l.width, h = l.height;
	const int pw = w + 2 * padW_, ph = h + 2 * padH_;
	for (int c = 0; c < kChannelCount; c++) {
		uint16_t *plane = levelBuf_.data() + c * planeStride_;
		uint16_t *inner = plane + padH_ * rowStride_ + padW_;
		if (params_.pyramidSmooth > 0)
			k_->smoothTri1(raw[c].data, raw[c].stride, inner, rowStride_, w, h,
						rowTmp_.data());
		else
			for (int y = 0; y < h; y++)
				std::memcpy(inner + y * rowStride_, raw[c].row(y), sizeof(uint16_t) * w);
		// Colour is padded by replication, gradients by zeros (the toolbox's padWith).
		const bool replicate = c < 3;
		for (int y = padH_; y < padH_ + h; y++) {
			uint16_t *row = plane + y * rowStride_;
			const uint16_t left = replicate ? row[padW_] : 0;
			const uint16_t right = replicate ? row[padW_ + w - 1] : 0;
			std::fill(row, row + padW_, left);
			std::fill(row + padW_ + w, row + pw, right);
		}
		for (int y = 0; y < padH_; y++) {
			uint16_t *top = plane + y * rowStride_;
			uint16_t *bottom = plane + (ph - 1 - y) * rowStride_;
			if (replicate) {
				std::memcpy(top, plane + padH_ * rowStride_, sizeof(uint16_t) * pw);
				std::memcpy(bottom, plane + (padH_ + h - 1) * rowStride_, sizeof(uint16_t) * pw);
			} else {
				std::fill(top, top + pw, 0);
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
