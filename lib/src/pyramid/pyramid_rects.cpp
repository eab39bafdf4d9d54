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
			Scratch &s = *scratch_[0];
			const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX, s);
			if (!xTaps)
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			const CellRange cols = sourceRows(xTaps, raw.cols);
			const kernels::ResampleTap *yTaps = levelTaps(i, kTapsY, s);
			if (!yTaps)
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			raw = LevelRect{ sourceRows(yTaps, raw.rows), cols };
		}
		const int c = l.source;
		addMerged(needRects_[c], needCount_[c], kMaxRects, raw, gap);
	}
	const auto t0 = StageClock::now();
	// The rectangles not computed yet this frame, and the colour rows they read.
	int tasks = 0;
	CellRange colour;
	for (int i = 0; i < scales_.count; i++)
		for (int k = 0; k < needCount_[i]; k++) {
			const LevelRect &r = needRects_[i][k];
			bool done = false;
			for (int d = 0; d < doneCount_[i] && !done; d++)
				done = doneRects_[i][d].contains(r);
			if (done)
				continue;
			const CellRange rows = colourRows(i, r);
			if (rows.empty() && !r.empty())
				return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
			colour.add(rows);
			tasks_[tasks++] = RectTask{ i, k, r.rows, long(r.rows.size()) * r.cols.size() };
		}
	convertLuvRows(input, colour);
	int parts = 0;
	const Status st = computeTasks(input, tasks, parts);
	if (!st.ok())
		return st;
	// Remember them, in the order of the levels (the oldest is forgotten when the list
	// is full: computed again if asked for again). The parts are done with their
	// rectangle: its first part names it. (std::sort: stable_sort may allocate.)
	std::sort(parts_, parts_ + parts, [](const RectTask &a, const RectTask &b) {
		if (a.level != b.level)
			return a.level < b.level;
		return a.index != b.index ? a.index < b.index : a.rows.begin < b.rows.begin;
	});
	for (int p = 0; p < parts; p++) {
		const int i = parts_[p].level;
		const LevelRect &r = needRects_[i][parts_[p].index];
		if (parts_[p].rows.begin != r.rows.begin)
			continue;
		if (doneCount_[i] == 0 && rows_[i].chan.empty())
			computedCount++;
		if (doneCount_[i] < kMaxRects) {
			doneRects_[i][doneCount_[i]++] = r;
		} else {
			doneRects_[i][doneNext_[i]] = r;
			doneNext_[i] = (doneNext_[i] + 1) % kMaxRects;
		}
		rectsComputed++;
	}
	msChannels += msSince(t0);
	return Status::success();
}

Status Pyramid::computeTasks(FrameInput &input, int tasks, int &parts)
{
	const int segments = cutIntoSegments(tasks);
	parts = segmentBegin_[segments];
	// Each part is computed into its own cells of the store, the same on any thread.
	auto one = [&](int seg, int worker) {
		for (int p = segmentBegin_[seg]; p < segmentBegin_[seg + 1]; p++) {
			const RectTask &part = parts_[p];
			const LevelRect piece{ part.rows, needRects_[part.level][part.index].cols };
			partFailed_[p] = !computeRect(input, part.level, piece, *scratch_[size_t(worker)]).ok();
		}
	};
	forEachTask(pool_, segments, one);
	for (int p = 0; p < parts; p++)
		if (partFailed_[p])
			return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
	return Status::success();
}

int Pyramid::cutIntoSegments(int tasks)
{
	const int threads = workers();
	segmentBegin_[0] = 0;
	if (threads == 1) {
		for (int t = 0; t < tasks; t++) {
			parts_[t] = tasks_[t];
			segmentBegin_[t + 1] = t + 1;
		}
		return tasks;
	}
	long total = 0;
	for (int t = 0; t < tasks; t++)
		total += tasks_[t].cells;
	const int wanted = std::min(2 * threads, kMaxSegments);
	const long unit = (total + wanted - 1) / wanted;
	// A part of fewer rows would compute more margin than cells.
	const int minRows = std::max(4, 8 * channelMargin_ / params_.shrink);
	int parts = 0, segments = 0;
	long filled = 0; // cells in the open segment
	auto close = [&] {
		segmentBegin_[++segments] = parts;
		filled = 0;
	};
	for (int t = 0; t < tasks; t++) {
		const RectTask &task = tasks_[t];
		const long cols = std::max(1L, task.cells / std::max(1, task.rows.size()));
		int row = task.rows.begin;
		while (row < task.rows.end) {
			const int left = task.rows.end - row;
			int take = left;
			// The last segment takes whatever is left.
			if (segments < kMaxSegments - 1 && long(left) * cols > unit - filled) {
				take = int((unit - filled + cols / 2) / cols);
				if (take < minRows)
					take = filled > 0 ? 0 : minRows; // close this one, or one small part
				if (left - take < minRows)
					take = left; // no sliver behind
			}
			if (take > 0) {
				parts_[parts++] = RectTask{ task.level, task.index, CellRange{ row, row + take },
							    cols * take };
				filled += cols * take;
				row += take;
			}
			if (take == 0 || filled >= unit || (row < task.rows.end && segments < kMaxSegments - 1))
				close();
		}
	}
	if (filled > 0)
		close();
	return segments;
}

CellRange Pyramid::colourRows(int i, const LevelRect &r)
{
	const PyramidLevel &l = scales_.levels[i];
	const int shrink = params_.shrink;
	const int w1 = l.width * shrink, h1 = l.height * shrink;
	const CellRange chan = CellRange{ shrink * r.rows.begin - channelMargin_, shrink * r.rows.end + channelMargin_ }
				     .clipped(h1);
	if (w1 == width_ && h1 == height_)
		return chan;
	const kernels::ResampleTap *yTaps = levelTaps(i, kTapsY, *scratch_[0]);
	return yTaps ? sourceRows(yTaps, chan) : CellRange();
}

Status Pyramid::computeRect(FrameInput &input, int i, const LevelRect &r, Scratch &s)
{
	const PyramidLevel &l = scales_.levels[i];
	const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
	// The colour pixels with the channels' margin on every side (whole cells), computed
	// into the approximation buffer (free between levels); only r is kept.
	const int shrink = params_.shrink;
	const CellRange chan = CellRange{ shrink * r.rows.begin - channelMargin_, shrink * r.rows.end + channelMargin_ }
				     .clipped(h1);
	const CellRange chanCols = CellRange{ shrink * r.cols.begin - channelMargin_, shrink * r.cols.end + channelMargin_ }
					 .clipped(w1);
	Plane<uint16_t> in[3];
	const Status st = levelColour(input, i, chan, chanCols, in, s);
	if (!st.ok())
		return st;
	Plane<uint16_t> scratch[kChannelCount];
	planesAt(s.approx.data(), chanCols.size() / shrink, chan.size() / shrink, scratch);
	Plane<const uint16_t> block[3];
	for (int c = 0; c < 3; c++)
		block[c] = { in[c].row(0) + chanCols.begin, chanCols.size(), chan.size(), in[c].stride };
	s.channels.compute(block, chanCols.size(), chan.size(), scratch);
	Plane<uint16_t> out[kChannelCount];
	realLevelPlanes(i, out);
	const int dy = chan.begin / shrink, dx = chanCols.begin / shrink;
	for (int c = 0; c < kChannelCount; c++)
		for (int y = r.rows.begin; y < r.rows.end; y++)
			std::memcpy(out[c].row(y) + r.cols.begin, scratch[c].row(y - dy) + (r.cols.begin - dx),
				    sizeof(uint16_t) * r.cols.size());
	return Status::success();
}

Status Pyramid::levelColour(FrameInput &input, int i, const CellRange &chan, const CellRange &chanCols,
			   Plane<uint16_t> in[3], Scratch &s)
{
	const PyramidLevel &l = scales_.levels[i];
	const int w1 = l.width * params_.shrink, h1 = l.height * params_.shrink;
	Plane<uint16_t> luv[3];
	for (int c = 0; c < 3; c++)
		luv[c] = luv_[c].view(width_, height_);
	// An image that exists already: its rows from chan.begin on.
	auto rowsOf = [&](const Plane<uint16_t> *image) {
		for (int c = 0; c < 3; c++)
			in[c] = Plane<uint16_t>{ image[c].row(chan.begin), w1, chan.size(), image[c].stride };
	};
	if (w1 == width_ && h1 == height_) {
		convertLuvRows(input, chan);
		rowsOf(luv);
		return Status::success();
	}
	// The half-size image, resampled already (computeBands), and the smaller octaves,
	// which are resampled from it.
	const bool fromHalf = halfLevel_ >= 0 && i >= halfLevel_;
	if (fromHalf) {
		const PyramidLevel &half = scales_.levels[halfLevel_];
		for (int c = 0; c < 3; c++)
			luv[c] = halfLuv_[c].view(half.width * params_.shrink, half.height * params_.shrink);
		if (i == halfLevel_) {
			rowsOf(luv);
			return Status::success();
		}
	}
	const kernels::ResampleTap *xTaps = levelTaps(i, kTapsX, s);
	const kernels::ResampleTap *yTaps = xTaps ? levelTaps(i, kTapsY, s) : nullptr;
	if (!yTaps)
		return Status::error(ErrorCode::InvalidArgument, "resampling ratio too large");
	// Resampled again from the whole (or half-size) image into the thread's scratch, from
	// its first row: a thread touches only as much of it as its largest part needs.
	if (!fromHalf)
		convertLuvRows(input, sourceRows(yTaps, chan));
	for (int c = 0; c < 3; c++)
		in[c] = s.levelLuv[c].view(w1, chan.size());
	const kernels::ResampleTap *yTapsOf[3] = { yTaps, yTaps, yTaps };
	resampleRows(luv, in, 3, yTapsOf, chan, xTaps, s, &chanCols, chan.begin);
	return Status::success();
}

} // namespace calped
