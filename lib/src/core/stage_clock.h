// SPDX-License-Identifier: BSD-2-Clause
// The clock every stage times itself with, for FrameStats.
#pragma once

#include <chrono>

namespace calped {

using StageClock = std::chrono::steady_clock;

inline double msSince(StageClock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(StageClock::now() - t0).count();
}

} // namespace calped
