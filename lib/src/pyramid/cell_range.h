// SPDX-License-Identifier: BSD-2-Clause
// Half-open ranges of a level's rows or columns (cells, or pixels of a level's image),
// and rectangles of them. The calibrated method needs each pyramid level only where a
// plausible pedestrian can stand; the pyramid follows these ranges back through
// smoothing, approximation, channel computation and resampling, so it computes nothing
// nobody reads (and everything it keeps is bit-identical to a full computation).
#pragma once

#include <algorithm>

#include "kernels.h"

namespace calped {

struct CellRange {
	int begin = 0;
	int end = 0;

	bool empty() const { return end <= begin; }
	int size() const { return end - begin; }
	bool contains(const CellRange &o) const { return o.empty() || (begin <= o.begin && o.end <= end); }
	// The smallest band holding both.
	void add(const CellRange &o)
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
	CellRange intersected(const CellRange &o) const
	{
		CellRange b{ std::max(begin, o.begin), std::min(end, o.end) };
		return b.empty() ? CellRange{} : b;
	}
	CellRange clipped(int rows) const
	{
		CellRange b{ std::max(begin, 0), std::min(end, rows) };
		return b.empty() ? CellRange{} : b;
	}
	CellRange grown(int margin, int rows) const
	{
		return empty() ? CellRange{} : CellRange{ begin - margin, end + margin }.clipped(rows);
	}
};

// A rectangle of a level: its rows and its columns (cells, before padding).
struct LevelRect {
	CellRange rows, cols;

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
inline CellRange sourceRows(const kernels::ResampleTap *taps, const CellRange &out)
{
	CellRange src;
	for (int o = out.begin; o < out.end; o++)
		src.add(CellRange{ taps[o].first, taps[o].first + taps[o].count });
	return src;
}

// taps[out.begin, out.end) with their first sample counted from row srcBegin, so the
// resampler can run on the band alone: output row k of the call is row out.begin + k.
inline void shiftTaps(const kernels::ResampleTap *taps, const CellRange &out, int srcBegin,
		      kernels::ResampleTap *shifted)
{
	for (int o = out.begin; o < out.end; o++) {
		shifted[o - out.begin] = taps[o];
		shifted[o - out.begin].first -= srcBegin;
	}
}

} // namespace calped
