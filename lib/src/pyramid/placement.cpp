// SPDX-License-Identifier: BSD-2-Clause
#include "pyramid/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace calped {

namespace {

// The raw channel rows of level i its band needs (the pyramid smoothing reaches a row).
CellRange rawRows(const ModelParams &p, const PyramidLevel &l, const CellRange &band)
{
	return band.clipped(l.height).grown(p.pyramidSmooth > 0 ? 1 : 0, l.height);
}

// Channel pixels of level r computed for the needed levels in [a, b) approximated from it
// (and its own band), as Pyramid::planRows would plan them.
double groupPixels(const ModelParams &p, const ScaleList &scales, const CellRange *levelRows,
		   int channelMargin, int r, int a, int b, std::vector<kernels::ResampleTap> &taps)
{
	const PyramidLevel &real = scales.levels[r];
	CellRange raw;
	for (int i = a; i < b; i++) {
		const PyramidLevel &l = scales.levels[i];
		const CellRange need = rawRows(p, l, levelRows[i]);
		if (need.empty())
			continue;
		if (i == r) {
			raw.add(need);
			continue;
		}
		kernels::buildResampleTaps(real.height, l.height, 1.0, taps.data());
		raw.add(sourceRows(taps.data(), need));
	}
	if (raw.empty())
		return 0;
	const int s = p.shrink; // pixels per cell
	const CellRange chan = CellRange{ s * raw.begin - channelMargin, s * raw.end + channelMargin }
				     .clipped(s * real.height);
	return double(chan.size()) * s * real.width;
}

} // namespace

int toolboxReach(const ModelParams &p) { return (p.nApprox + 2) / 2; }

bool choosePlacedLevels(const ModelParams &p, const ScaleList &scales, const CellRange *levelRows,
			  int channelMargin, int reach, int imageWidth, int imageHeight, int *source)
{
	const int n = scales.count;
	if (p.nApprox <= 0 || n <= 0 || reach < 1)
		return false;
	size_t most = size_t(std::max(imageWidth, imageHeight)) * 8 + 8;
	for (int i = 0; i < n; i++)
		most = std::max(most, size_t(scales.levels[i].height) + 8);
	std::vector<kernels::ResampleTap> taps(most);
	auto needed = [&](int i) { return !rawRows(p, scales.levels[i], levelRows[i]).empty(); };
	// A computed level is resampled from the image itself (the resampler's taps limit
	// how far it can shrink in one step).
	std::vector<char> computable(size_t(n), 0);
	for (int i = 0; i < n; i++) {
		const PyramidLevel &l = scales.levels[i];
		computable[i] = kernels::buildResampleTaps(imageWidth, p.shrink * l.width, 1.0, taps.data()) &&
				kernels::buildResampleTaps(imageHeight, p.shrink * l.height, 1.0, taps.data());
	}

	// Dynamic programming over the levels in order: best[j] is the least cost of levels
	// [0, j), each needed one served by a computed level of its group [i, j) within
	// reach. A computed level also costs a fixed overhead, so ties take fewer of them.
	const double inf = std::numeric_limits<double>::infinity();
	const double perLevel = 1024;
	std::vector<double> best(n + 1, inf);
	std::vector<int> groupStart(n + 1, -1), groupReal(n + 1, -1);
	best[0] = 0;
	for (int j = 1; j <= n; j++) {
		if (!needed(j - 1) && best[j - 1] < best[j]) {
			best[j] = best[j - 1];
			groupStart[j] = j - 1;
			groupReal[j] = -1; // level j - 1 alone, not computed
		}
		for (int i = std::max(0, j - 2 * reach - 1); i < j; i++) {
			if (best[i] == inf)
				continue;
			for (int r = std::max(i, j - 1 - reach); r <= std::min(j - 1, i + reach); r++) {
				if (!computable[r])
					continue;
				const double c = best[i] + perLevel +
						 groupPixels(p, scales, levelRows, channelMargin, r, i, j, taps);
				if (c < best[j]) {
					best[j] = c;
					groupStart[j] = i;
					groupReal[j] = r;
				}
			}
		}
	}
	if (best[n] == inf)
		return false;
	// Each group's levels take its computed level; levels nobody needs the nearest one.
	int computedCount = 0;
	for (int i = 0; i < n; i++)
		source[i] = -1;
	for (int j = n; j > 0; j = groupStart[j]) {
		if (groupReal[j] < 0)
			continue;
		computedCount++;
		for (int i = groupStart[j]; i < j; i++)
			if (needed(i) || i == groupReal[j])
				source[i] = groupReal[j];
	}
	if (computedCount == 0)
		return false;
	for (int i = 0; i < n; i++) {
		if (source[i] >= 0)
			continue;
		int nearest = -1;
		for (int k = 0; k < n; k++)
			if (source[k] == k && (nearest < 0 || std::abs(k - i) < std::abs(nearest - i)))
				nearest = k;
		source[i] = nearest;
	}
	return true;
}

void applyPlacedLevels(ScaleList &scales, const int *source)
{
	for (int i = 0; i < scales.count; i++) {
		scales.levels[i].computed = source[i] == i;
		scales.levels[i].source = source[i];
	}
}

double computedPixels(const ModelParams &p, const ScaleList &scales, const CellRange *levelRows,
		      int channelMargin)
{
	size_t most = 8;
	for (int i = 0; i < scales.count; i++)
		most = std::max(most, size_t(scales.levels[i].height) + 8);
	std::vector<kernels::ResampleTap> taps(most);
	std::vector<CellRange> served(size_t(scales.count));
	double total = 0;
	for (int r = 0; r < scales.count; r++) {
		if (!scales.levels[r].computed)
			continue;
		// Only the bands of the levels approximated from r (and its own).
		for (int i = 0; i < scales.count; i++)
			served[i] = scales.levels[i].source == r ? levelRows[i] : CellRange();
		total += groupPixels(p, scales, served.data(), channelMargin, r, 0, scales.count, taps);
	}
	return total;
}

} // namespace calped
