// SPDX-License-Identifier: BSD-2-Clause
// The resampling taps of every level (cached for maximum-size frames) and the resampler
// over bands of rows.
#include "pyramid/pyramid.h"
#include "pyramid/pyramid_util.h"

#include <cmath>

namespace calped {

using namespace pyramid_util;

bool Pyramid::tapSpec(const ScaleList &scales, int width, int height, int i, int kind, int &n,
		      int &m, double &gain) const
{
	const PyramidLevel &l = scales.levels[i];
	gain = 1.0;
	if (l.computed) {
		const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
		if ((w1 == width && h1 == height) || kind > kTapsY)
			return false; // the image itself
		const int half = halfLevelOf(params_, scales);
		const bool fromHalf = half >= 0 && i > half;
		const int srcW = fromHalf ? scales.levels[half].width * params_.shrink : width;
		const int srcH = fromHalf ? scales.levels[half].height * params_.shrink : height;
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

const kernels::ResampleTap *Pyramid::levelTaps(int i, int kind, Scratch &s)
{
	if (tapsCached_ && width_ == maxWidth_ && height_ == maxHeight_) {
		const size_t at = tapOffset_[i][kind];
		return at == kNoTaps ? nullptr : tapStore_.data() + at;
	}
	int n, m;
	double gain;
	if (!tapSpec(scales_, width_, height_, i, kind, n, m, gain))
		return nullptr;
	// Its own buffer per kind: a level's channel types are resampled together, each with
	// its own gain (one buffer for both gradient types gave the magnitude the histograms' gain).
	kernels::ResampleTap *out = s.taps[kind].data();
	return kernels::buildResampleTaps(n, m, gain, out) ? out : nullptr;
}

void Pyramid::resampleRows(const Plane<uint16_t> *src, const Plane<uint16_t> *dst, int planes,
			   const kernels::ResampleTap *const *yTaps, const CellRange &rows,
			   const kernels::ResampleTap *xTaps, Scratch &s, const CellRange *cols,
			   int dstFirstRow)
{
	// The planes share their source rows (the channel types' gains scale the weights
	// only), so one band of them serves every plane; each distinct yTaps is shifted once.
	CellRange srcRows;
	for (int p = 0; p < planes; p++)
		srcRows.add(sourceRows(yTaps[p], rows));
	const size_t bandTaps = s.yTapsBand.size() / kMaxTapSets;
	const kernels::ResampleTap *shiftedFrom[kMaxTapSets] = {};
	int sets = 0;
	kernels::PlaneJob jobs[kChannelCount];
	// Each output column depends only on its own taps, so a range of them is exact.
	const CellRange c = cols ? *cols : CellRange{ 0, dst[0].width };
	for (int p = 0; p < planes; p++) {
		int set = 0;
		while (set < sets && shiftedFrom[set] != yTaps[p])
			set++;
		kernels::ResampleTap *band = s.yTapsBand.data() + set * bandTaps;
		if (set == sets) {
			shiftTaps(yTaps[p], rows, srcRows.begin, band);
			shiftedFrom[sets++] = yTaps[p];
		}
		jobs[p] = { src[p].row(srcRows.begin), src[p].stride, dst[p].row(rows.begin - dstFirstRow) + c.begin,
			    dst[p].stride, band };
	}
	Plane<uint16_t> tmp = s.resampleTmp.view(c.size(), srcRows.size());
	k_->resamplePlanes(jobs, planes, src[0].width, srcRows.size(), c.size(), rows.size(),
			   xTaps + c.begin, tmp.data, tmp.stride);
}

} // namespace calped
