// SPDX-License-Identifier: BSD-2-Clause
// A level for the classifier: approximated from its computed level where need be,
// smoothed and padded, in the parts that were asked for.
#include "pyramid/pyramid.h"
#include "pyramid/pyramid_util.h"

#include <algorithm>
#include <cstring>

namespace calped {

using namespace pyramid_util;

void Pyramid::realLevelPlanes(int i, Plane<uint16_t> out[kChannelCount])
{
	const PyramidLevel &l = scales_.levels[i];
	planesAt(computedStore_.data() + realOffset_[i], l.width, l.height, out);
}

void Pyramid::approximate(int i, const CellRange &rows, const CellRange &cols,
			  Plane<uint16_t> out[kChannelCount], Scratch &s)
{
	const PyramidLevel &l = scales_.levels[i];
	Plane<uint16_t> src[kChannelCount];
	realLevelPlanes(l.source, src);
	planesAt(s.approx.data(), l.width, l.height, out);
	const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX, s);
	// Channel types: colour, magnitude, orientations; each has its power-law gain.
	const int typeOf[kChannelCount] = { 0, 0, 0, 1, 2, 2, 2, 2, 2, 2 };
	const kernels::ResampleTap *yTaps[kChannelCount];
	for (int c = 0; c < kChannelCount; c++) {
		yTaps[c] = c > 0 && typeOf[c] == typeOf[c - 1] ? yTaps[c - 1] : levelTaps(i, kTapsY + typeOf[c], s);
		if (!yTaps[c])
			return;
	}
	if (xTaps)
		resampleRows(src, out, kChannelCount, yTaps, rows, xTaps, s, &cols);
}

LevelChannels Pyramid::prepareRect(int i, const CellRange *only, const CellRange *onlyCols, Scratch &s)
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
		const auto t0 = StageClock::now();
		approximate(i, band, cols, raw, s);
		s.msApprox += msSince(t0);
	}

	const auto t0 = StageClock::now();
	const int w = l.width, h = l.height;
	const int pw = w + 2 * padW_, ph = h + 2 * padH_;
	for (int c = 0; c < kChannelCount; c++) {
		uint16_t *plane = s.levelBuf.data() + c * planeStride_;
		uint16_t *inner = plane + padH_ * rowStride_ + padW_;
		if (band.empty() || cols.empty())
			break;
		if (params_.pyramidSmooth > 0)
			k_->smoothTri1(raw[c].row(band.begin) + cols.begin, raw[c].stride,
				       inner + band.begin * rowStride_ + cols.begin, rowStride_,
				       cols.size(), band.size(), s.rowTmp.data());
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
	s.msSmooth += msSince(t0);

	LevelChannels out;
	out.data = s.levelBuf.data();
	out.paddedHeight = ph;
	out.paddedWidth = pw;
	out.rowStride = rowStride_;
	out.planeStride = planeStride_;
	return out;
}

} // namespace calped
