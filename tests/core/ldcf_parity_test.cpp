// SPDX-License-Identifier: BSD-2-Clause
// The toolbox's LDCF model (LdcfInriaDetector: shrink 2, four 5x5 filters per channel)
// against the toolbox on PETS frame 1: levels 1 (computed) and 2 (approximated) after the
// filter stage, 40 channels at half size, as acfDetect hands them to the trees.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "parity_util.h"
#include "pyramid/ldcf_filter.h"
#include "pyramid/pyramid.h"
#include "test_data.h"

using namespace calped;

namespace {

const char *const kName = "LdcfInriaDetector";

// Filtered channels are signed (the decorrelating filters sum to about zero): the
// tolerance is relative to the mean and maximum of |value|. Returns the floats read.
size_t compareFiltered(const LevelChannels &lc, int channels, const std::vector<float> &ref,
		       size_t offset, const char *what, double &worstMean, double &worstP99)
{
	const int h = lc.paddedHeight, w = lc.paddedWidth;
	const size_t n = size_t(h) * w;
	EXPECT_LE(offset + n * channels, ref.size()) << what;
	if (offset + n * channels > ref.size())
		return n * channels;
	for (int c = 0; c < channels; c++) {
		std::vector<double> d(n);
		double meanAbs = 0, meanRef = 0, maxRef = 0;
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				const double ours =
					(int(lc.data[c * lc.planeStride + y * lc.rowStride + x]) - kernels::kLdcfBias) /
					double(1 << kernels::kLdcfQ);
				const double theirs = ref[offset + y + size_t(h) * x + n * c];
				const size_t i = size_t(y) * w + x;
				d[i] = std::fabs(ours - theirs);
				meanAbs += d[i];
				meanRef += std::fabs(theirs);
				maxRef = std::max(maxRef, std::fabs(theirs));
			}
		meanAbs /= n;
		meanRef /= n;
		std::sort(d.begin(), d.end());
		const double p99 = d[std::min(n - 1, size_t(std::ceil(0.99 * n)) - 1)];
		const double meanPct = 100 * meanAbs / meanRef, p99Pct = 100 * p99 / maxRef;
		worstMean = std::max(worstMean, meanPct);
		worstP99 = std::max(worstP99, p99Pct);
		std::printf("%s filter %d channel %d: mean |diff| %.3f%% of mean |value|, p99 %.3f%% of max\n",
			    what, c / kChannelCount, c % kChannelCount, meanPct, p99Pct);
		// Issue 2's 1% holds for every filtered channel with the reference CPU's rcpps
		// (worst 0.80%, colour and magnitude under the zero-sum filters; with Intel's the
		// orientation channels under those filters were 1.2-2.7% away: docs/parity.md).
		EXPECT_LE(meanAbs, 0.01 * meanRef) << what << " channel " << c;
		EXPECT_LE(p99, 0.05 * maxRef) << what << " channel " << c;
	}
	return n * channels;
}

} // namespace

TEST(LdcfParity, FilterThresholdsKeepEverySplit)
{
	// For every biased Q12 value q and Q14 threshold T: q12 < T' exactly when 4 q12 < T.
	for (int32_t t : { -40000, -17, -16, -15, -1, 0, 1, 3, 4, 5, 16384, 72700, 131071, 131072,
			   131073, INT32_MAX, INT32_MIN }) {
		const int32_t moved = LdcfFilter::thresholdFor(t);
		for (int32_t u = 0; u < 65536; u += 1 + (u % 7)) {
			const int64_t q12 = int64_t(u) - kernels::kLdcfBias;
			EXPECT_EQ(u < moved, 4 * q12 < int64_t(t)) << "T " << t << " stored " << u;
		}
	}
}

TEST(LdcfParity, FilterIsMatlabConv2SameOnAnImpulse)
{
	// An impulse at (2, 3) of a 7x9 plane: conv2 'same' puts the filter itself, unflipped,
	// centred on it; everything else is 0 (the bias).
	const int w = 9, h = 7, size = 5;
	std::vector<uint16_t> src(size_t(w) * h, 0), dst(size_t(w) * h, 1);
	src[2 * w + 3] = 1 << kernels::kQ; // 1.0
	std::vector<int32_t> filter(size * size);
	for (int i = 0; i < size * size; i++)
		filter[i] = (i + 1) * 1000 * (i % 2 ? -1 : 1);
	kernels::ldcfFilter_ref(src.data(), w, w, h, filter.data(), size, dst.data(), w);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			const int a = y - 2 + 2, b = x - 3 + 2; // filter tap under output (y, x)
			const bool inside = a >= 0 && a < size && b >= 0 && b < size;
			// Q15 weight times 1.0 in Q14, down to Q12: weight / 8, rounded half up.
			const int32_t want = inside ? int32_t(std::floor(filter[a * size + b] / 8.0 + 0.5)) : 0;
			EXPECT_EQ(int(dst[y * w + x]) - kernels::kLdcfBias, want) << y << "," << x;
		}
}

TEST(LdcfParity, Frame1Levels1And2WithinTolerance)
{
	test::ToolboxFrame1 f;
	const test::Frame1 got = test::toolboxPyramidFrame1(kName, f);
	if (got == test::Frame1::Absent)
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	ASSERT_EQ(got, test::Frame1::Ready);
	Pyramid &pyr = f.pyramid;
	const Model &model = f.model;
	const std::vector<float> &ref = f.reference;
	const LevelChannels first = pyr.prepare(0);
	// Shrink 2 with 7 x 6 cells of padding: 302 x 396 before the filters.
	ASSERT_EQ(first.paddedHeight, 302);
	ASSERT_EQ(first.paddedWidth, 396);
	LdcfFilter filter;
	Status st = filter.init(model, first.paddedHeight, first.paddedWidth);
	ASSERT_TRUE(st.ok()) << st.message();
	double worstMean = 0, worstP99 = 0;
	// pyr_frame1_levels1-2.txt: 151 x 198 x 40 and 139 x 182 x 40.
	const LevelChannels l1 = filter.apply(first);
	ASSERT_EQ(l1.paddedHeight, 151);
	ASSERT_EQ(l1.paddedWidth, 198);
	const int channels = model.classifierChannels();
	ASSERT_EQ(channels, 40);
	const size_t n1 = compareFiltered(l1, channels, ref, 0, "LDCF level 1", worstMean, worstP99);
	const LevelChannels l2 = filter.apply(pyr.prepare(1));
	ASSERT_EQ(l2.paddedHeight, 139);
	ASSERT_EQ(l2.paddedWidth, 182);
	const size_t n2 = compareFiltered(l2, channels, ref, n1, "LDCF level 2", worstMean, worstP99);
	EXPECT_EQ(n1 + n2, ref.size());
	std::printf("LDCF levels 1-2, worst over 80 channels: mean %.3f%%, p99 %.3f%%\n", worstMean, worstP99);
}

// The toolbox's LDCF detections (after NMS) on PETS, frame by frame at native size (frames
// 1-20 of its 50, about 0.15 s a frame) and with the frame resized 2x first (dets_up2x:
// acfDetect on imResample(I, 2); frames 1-5 of its 100, about 0.5 s a frame): a few seconds,
// several times that under the sanitizers. docs/parity.md has the figures of longer runs.
TEST(LdcfParity, DetectionsNativeFrames1To20)
{
	const std::string shared = test::sharedDir();
	const std::string blob = test::toolboxModelBlob(kName);
	if (shared.empty() || blob.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	test::expectDetectionParity(blob,
				    shared + "/reference/dollar-toolbox-pets/" + kName +
					    "/dets_native_frames1-50.csv",
				    20, 1.0, ResizeAt::Frame, 0.95, ToolboxCpu::AmdEpyc);
}

TEST(LdcfParity, DetectionsResize2Frames1To5)
{
	const std::string shared = test::sharedDir();
	const std::string blob = test::toolboxModelBlob(kName);
	if (shared.empty() || blob.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	test::expectDetectionParity(blob,
				    shared + "/reference/dollar-toolbox-pets/" + kName +
					    "/dets_up2x_frames1-100.csv",
				    5, 2.0, ResizeAt::Frame, 0.95, ToolboxCpu::AmdEpyc);
}
