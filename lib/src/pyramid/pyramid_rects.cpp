// SPDX-License-Identifier: BSD-2-Clause
// Rectangles: a demand mapped to the computed levels' cells it needs, merged, and
// computed exactly with the channels' margin on every side.
#include "pyramid/pyramid.h"
#include "pyramid/pyramid_util.h"

#include <algorithm>
#include <cstring>

namespace calped {

using namespace pyramid_util;

Status Pyramid::computeRects(FrameInput &input, const int *levels, const LevelRect *rects, int count)
{
	const int reach = params_.pyramidSmooth > 0 ? 1 : 0;
	// What each computed level must hold: the raw rectangles of its own level and the
	// source rectangles of the levels approximated from it, merged. Merged rectangles
	// stay at least a cell margin apart, so their channels' margins do not overlap much.
	const int gap = 2 * channelMargin_ / params_.shrink;
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
	const auto t0 = StageClock::now();
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
	const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
	// The colour pixels with the channels' margin on every side (whole cells), computed
	// into the approximation buffer (free between levels); only r is kept.
	const int s = params_.shrink;
	const CellRange chan = CellRange{ s * r.rows.begin - channelMargin_, s * r.rows.end + channelMargin_ }
				     .clipped(h1);
	const CellRange chanCols = CellRange{ s * r.cols.begin - channelMargin_, s * r.cols.end + channelMargin_ }
					 .clipped(w1);
	Plane<uint16_t> in[3];
	const Status st = levelColour(input, i, chan, chanCols, in);
	if (!st.ok())
		return st;
	Plane<uint16_t> scratch[kChannelCount];
	planesAt(approx_.data(), chanCols.size() / s, chan.size() / s, scratch);
	Plane<const uint16_t> block[3];
	for (int c = 0; c < 3; c++)
		block[c] = { in[c].row(chan.begin) + chanCols.begin, chanCols.size(), chan.size(), in[c].stride };
	channels_.compute(block, chanCols.size(), chan.size(), scratch);
	Plane<uint16_t> out[kChannelCount];
	realLevelPlanes(i, out);
	const int dy = chan.begin / s, dx = chanCols.begin / s;
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

Status Pyramid::levelColour(FrameInput &input, int i, const CellRange &chan, const CellRange &chanCols,
			   Plane<uint16_t> in[3])
{
	const PyramidLevel &l = scales_.levels[i];
	const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
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

} // namespace calped
