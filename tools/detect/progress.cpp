// SPDX-License-Identifier: BSD-2-Clause
#include "progress.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace calped::apps {

RunStats::RunStats(long totalFrames)
	: total_(totalFrames), start_(Clock::now()), lastProgress_(start_)
{
	ms_.reserve(static_cast<size_t>(std::max(0L, std::min(totalFrames, 1L << 20))));
}

void RunStats::addFrame(double detectorMs, int detections)
{
	ms_.push_back(detectorMs);
	detections_ += static_cast<uint64_t>(std::max(detections, 0));
}

bool RunStats::progressDue()
{
	Clock::time_point now = Clock::now();
	if (now - lastProgress_ < std::chrono::seconds(2))
		return false;
	lastProgress_ = now;
	return true;
}

double RunStats::medianMs() const
{
	if (ms_.empty())
		return 0.0;
	std::vector<double> v = ms_;
	size_t mid = v.size() / 2;
	std::nth_element(v.begin(), v.begin() + mid, v.end());
	double hi = v[mid];
	if (v.size() % 2)
		return hi;
	double lo = *std::max_element(v.begin(), v.begin() + mid);
	return (lo + hi) / 2.0;
}

double RunStats::meanMs() const
{
	if (ms_.empty())
		return 0.0;
	return std::accumulate(ms_.begin(), ms_.end(), 0.0) / static_cast<double>(ms_.size());
}

double RunStats::wallSeconds() const
{
	return std::chrono::duration<double>(Clock::now() - start_).count();
}

void RunStats::printProgress() const
{
	double wall = wallSeconds();
	// A video's length is not known up front: then only the frames so far.
	char total[32] = "";
	if (total_ > 0)
		std::snprintf(total, sizeof(total), "/%ld", total_);
	std::fprintf(stderr, "calped-detect: %ld%s frames, detector %.1f ms/frame (mean), %.1f frames/s overall\n",
		     frames(), total, meanMs(), wall > 0 ? frames() / wall : 0.0);
}

void RunStats::printSummary(const char *method) const
{
	// Stable key=value format: scripts/run-main.sh reads it (documented in docs/cli.md).
	long n = frames();
	std::fprintf(stderr,
		     "calped-detect: summary: frames=%ld detections=%llu per_frame=%.2f "
		     "ms_median=%.2f ms_mean=%.2f wall_s=%.2f method=%s\n",
		     n, static_cast<unsigned long long>(detections_),
		     n ? static_cast<double>(detections_) / n : 0.0, medianMs(), meanMs(), wallSeconds(),
		     method);
}

} // namespace calped::apps
