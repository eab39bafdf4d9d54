// SPDX-License-Identifier: BSD-2-Clause
#include "search/generic_search.h"

#include <chrono>

namespace calped {

Status searchEveryWindow(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
			 Candidates &out, FrameStats &stats)
{
	using Clock = std::chrono::steady_clock;
	const Status st = pyramid.compute(input, PyramidDemand::wholeFrame());
	if (!st.ok())
		return st;
	const ScaleList &scales = pyramid.scales();
	for (int i = 0; i < scales.count; i++) {
		const LevelChannels level = pyramid.prepare(i);
		const auto t0 = Clock::now();
		out.classify(classifier, scales.levels[i], level, nullptr, 0, stats);
		stats.msClassify += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
		stats.levels++;
	}
	return Status::success();
}

} // namespace calped
