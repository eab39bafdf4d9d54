// SPDX-License-Identifier: BSD-2-Clause
// Shrink-2 aggregation (Caltech+, LDCF): the references against a plain double-precision
// transcription of the toolbox's formulas, and every kernel table against the references.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

std::vector<uint16_t> randomValues(std::mt19937 &rng, size_t n, int maxValue)
{
	std::uniform_int_distribution<int> d(0, maxValue);
	std::vector<uint16_t> v(n);
	for (auto &x : v)
		x = uint16_t(d(rng));
	return v;
}

// The toolbox's gradHist for bin 2 in doubles: orientation split (interpolate) or nearest;
// each pixel into its own cell, or (spatial) over the cells whose centres are within one
// cell at (x + .5) / 2 - .5, weights 1 - distance; all divided by bin^2; border cells of
// the spatial version times 8/7. Values in Q14 units.
std::vector<double> toolboxHist(const std::vector<uint16_t> &mag, const std::vector<uint16_t> &orient,
				int stride, int w, int h, int nOrients, bool interpolate, bool spatial)
{
	const int wb = w / 2, hb = h / 2;
	std::vector<double> H(size_t(nOrients) * wb * hb, 0.0);
	for (int y = 0; y < 2 * hb; y++)
		for (int x = 0; x < 2 * wb; x++) {
			const double m = mag[size_t(y) * stride + x] / 4.0;
			const double o = orient[size_t(y) * stride + x] / double(1 << kOrientQ);
			int o0 = int(o), o1 = o0 + 1 == nOrients ? 0 : o0 + 1;
			double m0 = m * (1 - (o - o0)), m1 = m * (o - o0);
			if (!interpolate) {
				o0 = int(std::floor(o + 0.5));
				if (o0 >= nOrients)
					o0 = 0;
				m0 = m;
				m1 = 0;
			}
			for (int cy = 0; cy < hb; cy++)
				for (int cx = 0; cx < wb; cx++) {
					double wgt;
					if (spatial) {
						const double dy = std::fabs((y + 0.5) / 2 - 0.5 - cy);
						const double dx = std::fabs((x + 0.5) / 2 - 0.5 - cx);
						wgt = (dy < 1 ? 1 - dy : 0) * (dx < 1 ? 1 - dx : 0);
					} else {
						wgt = (y / 2 == cy && x / 2 == cx) ? 1 : 0;
					}
					H[(size_t(o0) * hb + cy) * wb + cx] += wgt * m0;
					H[(size_t(o1) * hb + cy) * wb + cx] += wgt * m1;
				}
		}
	if (spatial)
		for (int o = 0; o < nOrients; o++)
			for (int cy = 0; cy < hb; cy++)
				for (int cx = 0; cx < wb; cx++) {
					double &v = H[(size_t(o) * hb + cy) * wb + cx];
					if (cy == 0 || cy == hb - 1)
						v *= 8.0 / 7.0;
					if (cx == 0 || cx == wb - 1)
						v *= 8.0 / 7.0;
				}
	return H;
}

} // namespace

TEST(Aggregate2, HistogramsFollowTheToolboxFormulas)
{
	std::mt19937 rng(21);
	for (const auto &size : { std::pair<int, int>{ 14, 10 }, { 9, 7 }, { 4, 2 }, { 33, 18 } })
		for (bool interpolate : { true, false })
			for (bool spatial : { true, false }) {
				const int w = size.first, h = size.second, stride = w + 3, nOrients = 6;
				const int wb = w / 2, hb = h / 2;
				// Magnitudes up to 1.0 (Q14), as the normalised channel gives them.
				const auto mag = randomValues(rng, size_t(stride) * h, 16384);
				const auto orient = randomValues(rng, size_t(stride) * h, (nOrients << kOrientQ) - 1);
				std::vector<uint16_t> out(size_t(nOrients) * wb * hb, 7);
				std::vector<uint16_t *> planes(nOrients);
				for (int o = 0; o < nOrients; o++)
					planes[o] = out.data() + size_t(o) * wb * hb;
				std::vector<uint32_t> scratch(2 * nOrients * (w + 4));
				gradHist2_ref(mag.data(), orient.data(), stride, w, h, nOrients, interpolate, spatial,
					      planes.data(), wb, scratch.data());
				const auto want = toolboxHist(mag, orient, stride, w, h, nOrients, interpolate, spatial);
				for (size_t i = 0; i < want.size(); i++)
					ASSERT_LE(std::fabs(out[i] - want[i]), 0.5 + 1e-9)
						<< w << "x" << h << " interpolate " << interpolate << " spatial " << spatial
						<< " value " << i << ": " << out[i] << " vs " << want[i];
			}
}

TEST(Aggregate2, BlockMeansRoundToNearest)
{
	std::mt19937 rng(22);
	for (int extra : { 0, 2 }) {
		const int w = 11, h = 9, stride = 13;
		const auto src = randomValues(rng, size_t(stride) * h, 65535);
		std::vector<uint16_t> out(size_t(w / 2) * (h / 2) + 1, 5);
		shrink2_ref(src.data(), stride, w, h, out.data(), w / 2, extra, nullptr);
		for (int cy = 0; cy < h / 2; cy++)
			for (int cx = 0; cx < w / 2; cx++) {
				const double sum = double(src[size_t(2 * cy) * stride + 2 * cx]) + src[size_t(2 * cy) * stride + 2 * cx + 1] +
						   src[size_t(2 * cy + 1) * stride + 2 * cx] + src[size_t(2 * cy + 1) * stride + 2 * cx + 1];
				const double want = sum / 4 / (1 << extra);
				ASSERT_LE(std::fabs(out[size_t(cy) * (w / 2) + cx] - want), 0.5) << cx << "," << cy;
			}
		EXPECT_EQ(out.back(), 5); // nothing written past the cells
	}
}

// Every table's kernels bit for bit against the references: sizes around the SIMD widths
// (8 and 16 pixels) with tails, too small for any cell, odd; random planes, and the
// largest inputs (every magnitude 65535 with a whole orientation weight: the 32-bit cell
// sums of the optimised kernels at their limit, the outputs saturated).
TEST(Aggregate2, EveryTableEqualsTheReferences)
{
	const KernelTable *all[8];
	const int count = availableKernelTables(all, 8);
	ASSERT_GE(count, 1);
	std::mt19937 rng(23);
	const std::pair<int, int> sizes[] = { { 37, 11 }, { 64, 16 }, { 3, 3 }, { 1, 5 }, { 6, 1 },
					      { 2, 2 }, { 16, 4 }, { 33, 9 }, { 50, 7 }, { 131, 6 } };
	for (int t = 0; t < count; t++) {
		const KernelTable *k = all[t];
		for (const auto &size : sizes)
			for (int extreme = 0; extreme < 3; extreme++)
				for (int nOrients : { 6, 1 }) {
					const int w = size.first, h = size.second, stride = w + 5;
					const int wb = w / 2, hb = h / 2;
					auto mag = randomValues(rng, size_t(stride) * h, 65535);
					auto orient = randomValues(rng, size_t(stride) * h, (nOrients << kOrientQ) - 1);
					if (extreme > 0) // whole bins: one orientation takes the full weight
						for (size_t i = 0; i < mag.size(); i++) {
							mag[i] = 65535;
							orient[i] = uint16_t((extreme == 1 ? 0 : i % nOrients) << kOrientQ);
						}
					std::vector<uint32_t> scratch(2 * nOrients * (w + 4));
					for (bool interpolate : { true, false })
						for (bool spatial : { true, false }) {
							std::vector<uint16_t> a(size_t(nOrients) * wb * hb + 1, 3), b = a;
							std::vector<uint16_t *> pa(nOrients), pb(nOrients);
							for (int o = 0; o < nOrients; o++) {
								pa[o] = a.data() + size_t(o) * wb * hb;
								pb[o] = b.data() + size_t(o) * wb * hb;
							}
							gradHist2_ref(mag.data(), orient.data(), stride, w, h, nOrients,
								      interpolate, spatial, pa.data(), wb, scratch.data());
							k->gradHist2(mag.data(), orient.data(), stride, w, h, nOrients,
								     interpolate, spatial, pb.data(), wb, scratch.data());
							ASSERT_EQ(a, b) << k->name << " gradHist2 " << w << "x" << h << " extreme "
									<< extreme << " nOrients " << nOrients << " interpolate "
									<< interpolate << " spatial " << spatial;
						}
					for (int extra : { 0, 2 }) {
						std::vector<uint16_t> a(size_t(wb) * hb + 1, 3), b = a;
						shrink2_ref(mag.data(), stride, w, h, a.data(), wb, extra, scratch.data());
						k->shrink2(mag.data(), stride, w, h, b.data(), wb, extra, scratch.data());
						ASSERT_EQ(a, b) << k->name << " shrink2 " << w << "x" << h << " extra " << extra;
					}
				}
	}
}
