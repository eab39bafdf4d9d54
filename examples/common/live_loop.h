// SPDX-License-Identifier: BSD-2-Clause
// The live loop every example runs: frames from any FrameSource through the detector,
// one JSON line per processed frame on stdout, stats on stderr, until --frames N, the end
// of a finite source, SIGINT/SIGTERM, or an error.
#pragma once

#include "frame_source.h"
#include "live_options.h"

namespace calped {
namespace live {

// Extra counters a port can add to the stats line (e.g. Aravis's resent packets).
class StatsReporter
{
public:
	virtual ~StatsReporter() = default;
	// Appends ", name value" pairs to `line` (capacity `size`); must not allocate.
	virtual void appendStats(char *line, size_t size) const = 0;
};

// Returns the exit status: 0 after --frames N or the end of the source; 128 + the signal
// after SIGINT/SIGTERM (tools/common/stop_signal.h: the frame being processed is finished
// and its line written); 1 on a runtime error (model, calibration, camera lost, no complete
// frame within --frame-timeout), reported on stderr as "PROGRAM: message". The source is
// started here and stopped before returning.
int runLive(ports::FrameSource &source, const LiveOptions &options, const char *program,
	    const StatsReporter *extra = nullptr);

} // namespace live
} // namespace calped
