// SPDX-License-Identifier: BSD-2-Clause
#include "search/generic_search.h"

#include "core/stage_clock.h"

namespace calped {

Status searchEveryWindow(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
			 Candidates &out, FrameStats &stats)
{
	const Status st = pyramid.compute(input, PyramidDemand::wholeFrame());
	if (!st.ok())
		return st;
	const ScaleList &scales = pyramid.scales();
	for (int i = 0; i < scales.count; i++) {
		const LevelChannels level = pyramid.prepare(i);
		const auto t0 = StageClock::now();
		out.classify(classifier, scales.levels[i], level, nullptr, 0, stats);
		stats.msClassify += msSince(t0);
		stats.levels++;
	}
	return Status::success();
}

} // namespace calped
