// SPDX-License-Identifier: BSD-2-Clause
// Per-run timing: progress lines while running and the closing summary.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

namespace calped::apps {

class RunStats
{
public:
	explicit RunStats(long totalFrames); // <= 0: unknown (videos)

	// Records one frame: the detector's own time (FrameStats::msTotal) and its detections.
	void addFrame(double detectorMs, int detections);

	// True at most every ~2 seconds, for long runs.
	bool progressDue();

	void printProgress() const; // "calped-detect: 120/795 frames, ..." on stderr
	// "calped-detect: summary: frames=... ms_median=... method=calibrated"
	void printSummary(const char *method) const;

	long frames() const { return static_cast<long>(ms_.size()); }
	uint64_t detections() const { return detections_; }
	double medianMs() const;
	double meanMs() const;
	double wallSeconds() const;

private:
	using Clock = std::chrono::steady_clock;
	long total_;
	std::vector<double> ms_;
	uint64_t detections_ = 0;
	Clock::time_point start_;
	Clock::time_point lastProgress_;
};

} // namespace calped::apps
