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
