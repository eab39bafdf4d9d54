// SPDX-License-Identifier: BSD-2-Clause
// The RGB8 resampler (input "resize") of every kernel table against the reference at many
// ratios: enlarging 1.01x..8x and shrinking, every width 1..40 (SIMD tails), odd sizes,
// strides wider than rows, unaligned starts and images of extremes, where halves and
// saturation are most frequent. Padding bytes must stay untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

std::vector<const KernelTable *> tablesUnderTest()
{
	const KernelTable *all[8];
	const int n = availableKernelTables(all, 8);
	return std::vector<const KernelTable *>(all + 1, all + n);
}

enum class Content { Random, Extremes, Smooth };

void fill(std::vector<uint8_t> &v, Content c, std::mt19937 &rng)
{
	for (size_t i = 0; i < v.size(); i++) {
		switch (c) {
		case Content::Random: v[i] = uint8_t(rng()); break;
		case Content::Extremes: v[i] = rng() % 2 ? 255 : uint8_t(rng() % 3); break;
		case Content::Smooth: v[i] = uint8_t(128 + 100 * std::sin(0.05 * double(i)) + rng() % 3); break;
		}
	}
}

// Resamples an n x nh image to m x mh with every table; false (and a gtest failure) on a
// difference. Returns true without testing when the taps cannot be built.
bool sameAsReference(int n, int nh, int m, int mh, std::mt19937 &rng, Content content = Content::Random)
{
	std::vector<ResampleTap> xt(m), yt(mh);
	if (!buildResampleTaps(n, m, 1.0, xt.data()) || !buildResampleTaps(nh, mh, 1.0, yt.data()))
		return true;
	const int srcStride = 3 * n + int(rng() % 7), dstStride = 3 * m + int(rng() % 5);
	const int offset = int(rng() % 3);
	std::vector<uint8_t> src(size_t(srcStride) * nh + offset);
	fill(src, content, rng);
	std::vector<uint8_t> want(size_t(dstStride) * mh + offset + 7, 0xA5);
	std::vector<int32_t> row(3 * size_t(n) + 8);
	resampleRgb8_ref(src.data() + offset, srcStride, n, nh, want.data() + offset, dstStride, m, mh,
			 xt.data(), yt.data(), row.data());
	for (const KernelTable *k : tablesUnderTest()) {
		std::vector<uint8_t> got(want.size(), 0xA5);
		k->resampleRgb8(src.data() + offset, srcStride, n, nh, got.data() + offset, dstStride, m, mh,
				xt.data(), yt.data(), row.data());
		EXPECT_EQ(want, got) << k->name << " " << n << "x" << nh << " -> " << m << "x" << mh
				     << " strides " << srcStride << ", " << dstStride << " offset " << offset;
		if (want != got)
			return false;
	}
	return true;
}

int scaled(int n, double r)
{
	return std::max(1, int(std::lround(n * r)));
}

} // namespace

TEST(ResampleRgb8, ManyRatios)
{
	std::mt19937 rng(21);
	const double ratios[] = { 1.01, 1.07, 1.1, 1.2, 1.25, 1.3333, 1.5, 1.6, 1.75, 1.9, 2.0, 2.1,
				  2.25, 2.5, 2.75, 3.0, 3.3, 3.7, 4.0, 4.5, 5.5, 6.0, 8.0,
				  0.95, 0.9, 0.8, 0.75, 0.6667, 0.6, 0.5, 0.45, 0.4, 0.35, 0.3,
				  0.25, 0.2, 0.15, 0.12 };
	const int widths[] = { 23, 64, 97, 150 };
	for (double r : ratios)
		for (int n : widths)
			for (Content c : { Content::Random, Content::Extremes, Content::Smooth }) {
				const int nh = 7 + n % 13;
				ASSERT_TRUE(sameAsReference(n, nh, scaled(n, r), scaled(nh, r), rng, c)) << "ratio " << r;
			}
}

TEST(ResampleRgb8, DifferentRatiosPerAxis)
{
	std::mt19937 rng(22);
	const double ratios[] = { 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 2.5, 3.3 };
	for (double rx : ratios)
		for (double ry : ratios)
			ASSERT_TRUE(sameAsReference(41, 17, scaled(41, rx), scaled(17, ry), rng)) << rx << " " << ry;
}

TEST(ResampleRgb8, EveryWidthUpTo40)
{
	std::mt19937 rng(23);
	const double ratios[] = { 1.01, 1.5, 2.0, 2.5, 3.0, 8.0, 0.7, 0.5 };
	for (int n = 1; n <= 40; n++)
		for (double r : ratios)
			ASSERT_TRUE(sameAsReference(n, 5, scaled(n, r), scaled(5, r), rng)) << "ratio " << r;
	// Every output width 1..40 from a few source widths.
	for (int n : { 1, 2, 6, 11, 19, 40 })
		for (int m = 1; m <= 40; m++)
			ASSERT_TRUE(sameAsReference(n, 3, m, 4, rng));
}

TEST(ResampleRgb8, RandomSizes)
{
	std::mt19937 rng(24);
	for (int i = 0; i < 300; i++) {
		const int n = 1 + int(rng() % 200), nh = 1 + int(rng() % 12);
		const int m = 1 + int(rng() % 400), mh = 1 + int(rng() % 24);
		ASSERT_TRUE(sameAsReference(n, nh, m, mh, rng, i % 2 ? Content::Random : Content::Extremes));
	}
}

TEST(ResampleRgb8, PetsFrameSizes)
{
	// The detector's own case: a 768 x 576 frame at the configured resizes.
	std::mt19937 rng(25);
	for (double r : { 1.5, 2.0, 2.5 })
		ASSERT_TRUE(sameAsReference(768, 576, scaled(768, r), scaled(576, r), rng)) << "ratio " << r;
}
