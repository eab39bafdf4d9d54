// SPDX-License-Identifier: BSD-2-Clause
// LDCF's filter kernel: every kernel table against the reference, bit for bit, on planes
// of every shape the vector loops treat differently (narrower than a block, one block and
// a bit, strides wider than the plane), full-range samples and weights (the sums overflow
// 32 bits in the reference's arithmetic), saturation both ways, and the weight +1.0 that
// the vector versions leave to the reference.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

void expectEqualToReference(const std::vector<uint16_t> &src, int stride, int w, int h,
			    const std::vector<int32_t> &filter, const char *what)
{
	const int dstStride = w + 5;
	std::vector<uint16_t> want(size_t(dstStride) * h, 7), got;
	ldcfFilter_ref(src.data(), stride, w, h, filter.data(), 5, want.data(), dstStride);
	const KernelTable *tables[8];
	const int n = availableKernelTables(tables, 8);
	for (int t = 0; t < n; t++) {
		const KernelTable *k = tables[t];
		got.assign(want.size(), 7);
		k->ldcfFilter(src.data(), stride, w, h, filter.data(), 5, got.data(), dstStride);
		ASSERT_EQ(got, want) << k->name << " " << what << " " << w << "x" << h << " stride " << stride;
	}
}

} // namespace

TEST(LdcfFilterKernel, EveryTableEqualsTheReference)
{
	std::mt19937 rng(20);
	std::uniform_int_distribution<int> sample(0, 65535), weight(-32768, 32767), small(0, 2000);
	const int sizes[][2] = { { 1, 1 }, { 3, 7 }, { 5, 5 }, { 19, 6 }, { 20, 20 }, { 21, 9 },
				 { 36, 11 }, { 37, 40 }, { 198, 151 }, { 396, 31 } };
	for (const auto &s : sizes)
		for (int extra : { 0, 13 }) {
			const int w = s[0], h = s[1], stride = w + extra;
			std::vector<uint16_t> src(size_t(stride) * h);
			std::vector<int32_t> filter(25);
			// Full-range samples and weights, then channel-like values and unit-norm-like
			// weights (the detector's case).
			for (auto &v : src)
				v = uint16_t(sample(rng));
			for (auto &f : filter)
				f = weight(rng);
			expectEqualToReference(src, stride, w, h, filter, "full range");
			for (auto &v : src)
				v = uint16_t(small(rng));
			for (auto &f : filter)
				f /= 5;
			expectEqualToReference(src, stride, w, h, filter, "channel-like");
		}
}

TEST(LdcfFilterKernel, ExtremesSaturateAsTheReference)
{
	const int w = 40, h = 12;
	std::vector<uint16_t> src(size_t(w) * h, 65535);
	for (int32_t wgt : { 32767, -32768, 1, -1 }) {
		std::vector<int32_t> filter(25, wgt);
		expectEqualToReference(src, w, w, h, filter, "constant filter");
	}
	// +1.0 (2^15) is not an int16: the vector versions hand such a filter to the reference.
	std::vector<int32_t> impulse(25, 0);
	impulse[12] = 32768;
	expectEqualToReference(src, w, w, h, impulse, "impulse of weight 1.0");
	std::mt19937 rng(21);
	for (auto &v : src)
		v = uint16_t(rng());
	expectEqualToReference(src, w, w, h, impulse, "impulse of weight 1.0, random plane");
}

// One cell of the filtered, half-size plane on its own (ldcfCell, LdcfFilter::onDemand):
// every table's, at every output, equals the whole plane filtered (ldcfFilter_ref) and
// resampled (resamplePlane_ref); odd and even sizes (two or three taps), cells at every
// distance from the edges, full-range samples, weights of +-1.0 (which do not pack: the
// vector versions then run the reference), sizes 5 and 3.
TEST(LdcfCellKernel, EveryTableEqualsTheWholePlaneFilteredAndResampled)
{
	std::mt19937 rng(21);
	std::uniform_int_distribution<int> sample(0, 65535), weight(-32768, 32768), small(0, 2000);
	const KernelTable *tables[8];
	const int n = availableKernelTables(tables, 8);
	size_t compared = 0;
	const int sizes[][2] = { { 1, 1 }, { 2, 3 }, { 5, 5 }, { 9, 14 }, { 12, 12 }, { 23, 18 }, { 40, 31 } };
	for (const auto &s : sizes)
		for (int size : { 5, 3 })
			for (int range = 0; range < 3; range++) {
				const int w = s[0], h = s[1], stride = w + 3, mw = (w + 1) / 2, mh = (h + 1) / 2;
				std::vector<uint16_t> src(size_t(stride) * h);
				std::vector<int32_t> filter(size_t(size) * size);
				for (auto &v : src)
					v = uint16_t(range == 1 ? small(rng) : sample(rng));
				for (auto &f : filter)
					f = range == 2 ? (rng() % 2 ? 32768 : -32768) : weight(rng);
				std::vector<uint16_t> full(size_t(w) * h), tmp(size_t(mw) * h), want(size_t(mw) * mh);
				std::vector<ResampleTap> xTaps(size_t(mw) + 1), yTaps(size_t(mh) + 1);
				ASSERT_TRUE(buildResampleTaps(w, mw, 1.0, xTaps.data()));
				ASSERT_TRUE(buildResampleTaps(h, mh, 1.0, yTaps.data()));
				std::vector<int16_t> packed(kLdcfPackedCount);
				const bool packs = packLdcfCellFilter(filter.data(), size, packed.data());
				EXPECT_EQ(packs, size == 5 && range != 2);
				const LdcfCellFilter cellFilter{ filter.data(), size, packs ? packed.data() : nullptr };
				ldcfFilter_ref(src.data(), stride, w, h, filter.data(), size, full.data(), w);
				resamplePlane_ref(full.data(), w, w, h, want.data(), mw, mw, mh, xTaps.data(),
						  yTaps.data(), tmp.data(), mw);
				for (int t = 0; t < n; t++)
					for (int y = 0; y < mh; y++)
						for (int x = 0; x < mw; x++) {
							const uint16_t got = tables[t]->ldcfCell(src.data(), stride, w, h,
												 cellFilter, xTaps[size_t(x)],
												 yTaps[size_t(y)]);
							ASSERT_EQ(got, want[size_t(y) * mw + x])
								<< tables[t]->name << " " << w << "x" << h << " filter " << size
								<< " range " << range << " cell " << y << "," << x;
							compared++;
						}
			}
	EXPECT_GT(compared, 5000u);
}
