// SPDX-License-Identifier: BSD-2-Clause
// Half-open ranges of rows. The calibrated mode needs each pyramid level only in the
// rows where a plausible pedestrian can stand; the pyramid follows those ranges back
// through smoothing, approximation, channel computation and resampling, so it computes
// no row nobody reads (and every row it keeps is bit-identical to a full computation).
#pragma once

#include <algorithm>

#include "kernels.h"

namespace calped {

struct RowBand {
	int begin = 0;
	int end = 0;

	bool empty() const { return end <= begin; }
	int size() const { return end - begin; }
	bool contains(const RowBand &o) const { return o.empty() || (begin <= o.begin && o.end <= end); }
	// The smallest band holding both.
	void add(const RowBand &o)
	{
		if (o.empty())
			return;
		if (empty()) {
			*this = o;
			return;
		}
		begin = std::min(begin, o.begin);
		end = std::max(end, o.end);
	}
	// The rows in both.
	RowBand intersected(const RowBand &o) const
	{
		RowBand b{ std::max(begin, o.begin), std::min(end, o.end) };
		return b.empty() ? RowBand{} : b;
	}
	RowBand clipped(int rows) const
	{
		RowBand b{ std::max(begin, 0), std::min(end, rows) };
		return b.empty() ? RowBand{} : b;
	}
	RowBand grown(int margin, int rows) const
	{
		return empty() ? RowBand{} : RowBand{ begin - margin, end + margin }.clipped(rows);
	}
};

// A rectangle of a level: its rows and its columns (cells, before padding).
struct LevelRect {
	RowBand rows, cols;

	bool empty() const { return rows.empty() || cols.empty(); }
	bool contains(const LevelRect &o) const
	{
		return o.empty() || (rows.contains(o.rows) && cols.contains(o.cols));
	}
	// Whether the two overlap or are less than `gap` cells apart.
	bool near(const LevelRect &o, int gap) const
	{
		return rows.begin < o.rows.end + gap && o.rows.begin < rows.end + gap &&
		       cols.begin < o.cols.end + gap && o.cols.begin < cols.end + gap;
	}
	// The smallest rectangle holding both.
	void add(const LevelRect &o)
	{
		if (o.empty())
			return;
		if (empty()) {
			*this = o;
			return;
		}
		rows.add(o.rows);
		cols.add(o.cols);
	}
};

// Adds r to set[0 .. count), rectangles at least `gap` cells apart: every one near r is
// merged into it (their bounding box), until none is; at `capacity`, the last one is
// merged in too. The union only grows, so everything added stays covered.
inline void addMerged(LevelRect *set, int &count, int capacity, LevelRect r, int gap)
{
	if (r.empty())
		return;
	for (int k = 0; k < count;) {
		if (set[k].near(r, gap)) {
			r.add(set[k]);
			set[k] = set[--count];
			k = 0; // r grew: look again from the start
		} else {
			k++;
		}
	}
	while (count >= capacity) {
		r.add(set[--count]);
		for (int k = 0; k < count;) {
			if (set[k].near(r, gap)) {
				r.add(set[k]);
				set[k] = set[--count];
				k = 0;
			} else {
				k++;
			}
		}
	}
	set[count++] = r;
}

// The source rows that resampling reads to produce output rows `out`.
inline RowBand sourceRows(const kernels::ResampleTap *taps, const RowBand &out)
{
	RowBand src;
	for (int o = out.begin; o < out.end; o++)
		src.add(RowBand{ taps[o].first, taps[o].first + taps[o].count });
	return src;
}

// taps[out.begin, out.end) with their first sample counted from row srcBegin, so the
// resampler can run on the band alone: output row k of the call is row out.begin + k.
inline void shiftTaps(const kernels::ResampleTap *taps, const RowBand &out, int srcBegin,
		      kernels::ResampleTap *shifted)
{
	for (int o = out.begin; o < out.end; o++) {
		shifted[o - out.begin] = taps[o];
		shifted[o - out.begin].first -= srcBegin;
	}
}

} // namespace calped
