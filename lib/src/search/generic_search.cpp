// SPDX-License-Identifier: BSD-2-Clause
#include "search/generic_search.h"

#include "core/stage_clock.h"

namespace calped {

Status searchEveryWindow(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
			 Candidates &out, FrameStats &stats, ThreadPool *pool)
{
	const Status st = pyramid.compute(input, PyramidDemand::wholeFrame());
	if (!st.ok())
		return st;
	const ScaleList &scales = pyramid.scales();
	LevelHits hits[kMaxLevels];
	double ms[kMaxLevels];
	out.emptyLanes();
	auto one = [&](int i, int worker) {
		const LevelChannels level = pyramid.classifierLevel(i, nullptr, 0, worker);
		const auto t0 = StageClock::now();
		hits[i] = out.classifyInLane(worker, classifier, scales.levels[i], level, nullptr, 0);
		ms[i] = msSince(t0);
	};
	forEachTask(pool, scales.count, one);
	out.gather(hits, scales.count, stats);
	for (int i = 0; i < scales.count; i++)
		stats.msClassify += ms[i];
	stats.levels += scales.count;
	return Status::success();
}

} // namespace calped
