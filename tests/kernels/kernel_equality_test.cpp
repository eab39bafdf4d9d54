// SPDX-License-Identifier: BSD-2-Clause
// Every optimised kernel against the scalar reference: random inputs, odd widths and
// heights, strides wider than rows and unaligned starts (base pointers one element past an
// aligned address, for inputs and outputs); outputs must be bit-identical.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

struct Size {
	int w, h;
};
const Size kSizes[] = { { 1, 1 }, { 2, 3 }, { 3, 2 }, { 5, 7 }, { 8, 8 }, { 13, 11 },
			{ 16, 17 }, { 31, 9 }, { 33, 40 }, { 64, 3 }, { 67, 29 }, { 129, 21 } };

std::vector<uint16_t> randomPlane(std::mt19937 &rng, size_t n, int maxValue)
{
	std::uniform_int_distribution<int> d(0, maxValue);
	std::vector<uint16_t> v(n);
	for (auto &x : v)
		x = uint16_t(d(rng));
	return v;
}

// The tables under test: every one the build and CPU provide besides the reference.
std::vector<const KernelTable *> tablesUnderTest()
{
	const KernelTable *all[8];
	const int n = availableKernelTables(all, 8);
	return std::vector<const KernelTable *>(all + 1, all + n);
}

} // namespace

TEST(KernelTables, NeonTableOnNeonTargets)
{
	// An ARM build with NEON must compare the NEON kernels here, not silently fall back to
	// the portable ones (a build-configuration mistake the equality tests cannot see);
	// -Dsimd=none leaves them out on purpose.
	bool haveNeon = false;
	for (const KernelTable *k : tablesUnderTest())
		haveNeon = haveNeon || std::string(k->name) == "neon";
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
	const bool expectNeon = CALPED_SIMD_ENABLED;
#else
	const bool expectNeon = false;
#endif
	EXPECT_EQ(haveNeon, expectNeon);
	if (expectNeon) {
		EXPECT_STREQ(bestKernels().name, "neon");
	}
}

TEST(KernelEquality, SmoothTri1)
{
	std::mt19937 rng(1);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (int extra : { 0, 3 }) {
				const int stride = s.w + extra, offset = extra ? 1 : 0;
				auto src = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
				std::vector<uint16_t> a(size_t(stride) * s.h + 1, 7), b = a;
				std::vector<uint32_t> tmp(s.w + 8);
				smoothTri1_ref(src.data() + offset, stride, a.data() + offset, stride, s.w, s.h, tmp.data());
				k->smoothTri1(src.data() + offset, stride, b.data() + offset, stride, s.w, s.h, tmp.data());
				ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h << " stride " << stride;
			}
}

TEST(KernelEquality, TriangleSum)
{
	std::mt19937 rng(2);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (int r : { 1, 2, 3, 5, 8, 9 }) // 9: past the unrolled radii
				for (int offset : { 0, 1 }) {
					const int stride = s.w + 2;
					auto src = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
					std::vector<uint32_t> a(size_t(stride) * s.h + offset, 9), b = a;
					std::vector<uint32_t> scratch(triSumScratchSize(s.w, s.h, r));
					triSumR_ref(src.data() + offset, stride, a.data() + offset, stride, s.w, s.h, r, scratch.data());
					k->triSum(src.data() + offset, stride, b.data() + offset, stride, s.w, s.h, r, scratch.data());
					ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h << " r " << r << " offset " << offset;
				}
}

TEST(KernelEquality, ResamplePlane)
{
	std::mt19937 rng(3);
	const int sizes[] = { 1, 2, 3, 5, 8, 13, 16, 29, 40, 67 };
	for (const KernelTable *k : tablesUnderTest())
		for (int sw : sizes)
			for (int dw : sizes)
				for (double gain : { 1.0, 1.07, 0.93 }) {
					const int sh = sw + 3, dh = dw + 1;
					std::vector<ResampleTap> xt(dw), yt(dh);
					if (!buildResampleTaps(sw, dw, 1.0, xt.data()) ||
					    !buildResampleTaps(sh, dh, gain, yt.data()))
						continue; // shrinking by more than the taps allow
					const int offset = dw % 2; // unaligned starts for odd output widths
					auto src = randomPlane(rng, size_t(sw + 1) * sh + offset, 65535);
					std::vector<uint16_t> a(size_t(dw + 2) * dh + offset, 1), b = a;
					std::vector<uint16_t> tmp(size_t(dw) * sh + offset);
					resamplePlane_ref(src.data() + offset, sw + 1, sw, sh, a.data() + offset, dw + 2, dw, dh, xt.data(), yt.data(), tmp.data() + offset, dw);
					k->resamplePlane(src.data() + offset, sw + 1, sw, sh, b.data() + offset, dw + 2, dw, dh, xt.data(), yt.data(), tmp.data() + offset, dw);
					ASSERT_EQ(a, b) << k->name << " " << sw << "->" << dw << " gain " << gain;
				}
}

TEST(KernelEquality, ResamplePlaneHalvingAndLongRows)
{
	// Widths with several full SIMD blocks, exact halving (the computed octaves), the
	// ratios of approximated levels and larger shrinking ratios (the smaller octaves).
	std::mt19937 rng(10);
	const std::pair<int, int> widths[] = { { 64, 32 }, { 130, 65 }, { 96, 48 }, { 192, 176 },
					       { 144, 161 }, { 200, 117 }, { 97, 103 },
					       { 256, 64 }, { 301, 40 }, { 150, 51 } }; // and shrinking by 3 to 8
	for (const KernelTable *k : tablesUnderTest())
		for (auto [sw, dw] : widths)
			for (int offset : { 0, 1 }) {
				const int sh = 9, dh = 5;
				std::vector<ResampleTap> xt(dw), yt(dh);
				ASSERT_TRUE(buildResampleTaps(sw, dw, 1.0, xt.data()));
				ASSERT_TRUE(buildResampleTaps(sh, dh, 1.05, yt.data()));
				auto src = randomPlane(rng, size_t(sw + 3) * sh + offset, 65535);
				std::vector<uint16_t> a(size_t(dw) * dh + offset, 1), b = a, tmp(size_t(dw) * sh + offset);
				resamplePlane_ref(src.data() + offset, sw + 3, sw, sh, a.data() + offset, dw, dw, dh, xt.data(), yt.data(), tmp.data() + offset, dw);
				k->resamplePlane(src.data() + offset, sw + 3, sw, sh, b.data() + offset, dw, dw, dh, xt.data(), yt.data(), tmp.data() + offset, dw);
				ASSERT_EQ(a, b) << k->name << " " << sw << "->" << dw << " offset " << offset;
			}
}

TEST(KernelEquality, ResamplePlanesShareOnePlan)
{
	// Several planes with their own strides and gains (the channels of a level) in one
	// call, each equal to the reference on that plane alone: widths past one chunk of
	// planned blocks (512 outputs, with a remainder shorter than a block), the ratios of
	// approximated levels, exact halving, the largest weights the 16-bit multiply takes
	// (gain 1.99) and beyond (gain 2.3), and the sizes of PETS's placed levels.
	std::mt19937 rng(12);
	const std::pair<int, int> widths[] = { { 249, 384 }, { 249, 209 }, { 768, 996 }, { 768, 592 },
					       { 1100, 1030 }, { 700, 1027 }, { 1040, 520 }, { 20, 9 } };
	const double gains[] = { 1.0, 1.07, 0.93, 1.99, 2.3 };
	for (const KernelTable *k : tablesUnderTest())
		for (auto [sw, dw] : widths) {
			const int sh = 13, dh = 17, planes = 5;
			std::vector<ResampleTap> xt(dw), yt(size_t(dh) * planes);
			ASSERT_TRUE(buildResampleTaps(sw, dw, 1.0, xt.data()));
			std::vector<std::vector<uint16_t>> src, want, got;
			std::vector<PlaneJob> jobs;
			for (int p = 0; p < planes; p++) {
				ASSERT_TRUE(buildResampleTaps(sh, dh, gains[p], yt.data() + p * dh));
				src.push_back(randomPlane(rng, size_t(sw + p) * sh + 1, 65535));
				want.emplace_back(size_t(dw + 3) * dh + 1, 7);
				got.push_back(want.back());
			}
			std::vector<uint16_t> tmp(size_t(dw) * sh);
			for (int p = 0; p < planes; p++) {
				resamplePlane_ref(src[p].data() + 1, sw + p, sw, sh, want[p].data() + 1, dw + 3, dw,
						  dh, xt.data(), yt.data() + p * dh, tmp.data(), dw);
				jobs.push_back({ src[p].data() + 1, sw + p, got[p].data() + 1, dw + 3,
						 yt.data() + p * dh });
			}
			k->resamplePlanes(jobs.data(), planes, sw, sh, dw, dh, xt.data(), tmp.data(), dw);
			for (int p = 0; p < planes; p++)
				ASSERT_EQ(want[p], got[p]) << k->name << " " << sw << "->" << dw << " plane " << p;
		}
}

TEST(KernelEquality, ResampleTapsKeepFlatInputFlat)
{
	// A constant image resampled with gain 1 stays exactly constant.
	for (int n : { 3, 16, 100, 576 })
		for (int m : { 1, 7, 50, 288, 1152 }) {
			std::vector<ResampleTap> t(m);
			if (!buildResampleTaps(n, m, 1.0, t.data()))
				continue;
			for (int o = 0; o < m; o++) {
				int sum = 0;
				for (int j = 0; j < t[o].count; j++)
					sum += t[o].weight[j];
				ASSERT_EQ(sum, kOne) << n << "->" << m << " output " << o;
			}
		}
}

TEST(KernelEquality, GradientMagnitudeOrientation)
{
	std::mt19937 rng(4);
	GradientTables t;
	buildGradientTables(t, 6, 5, 0.005);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (int maxValue : { 65535, 300, 3 }) { // strong edges, weak ones, near-flat
				const int stride = s.w + 5, offset = maxValue == 300 ? 1 : 0;
				std::vector<uint16_t> planes[3];
				const uint16_t *p[3];
				for (int c = 0; c < 3; c++) {
					planes[c] = randomPlane(rng, size_t(stride) * s.h + offset, maxValue);
					p[c] = planes[c].data() + offset;
				}
				std::vector<uint16_t> ma(size_t(stride) * s.h + offset, 1), oa = ma, mb = ma, ob = ma;
				std::vector<int32_t> scratch(4 * s.w + 16);
				gradMagOrient_ref(t, p, stride, s.w, s.h, ma.data() + offset, oa.data() + offset, stride, scratch.data());
				k->gradMagOrient(t, p, stride, s.w, s.h, mb.data() + offset, ob.data() + offset, stride, scratch.data());
				ASSERT_EQ(ma, mb) << k->name << " magnitude " << s.w << "x" << s.h;
				ASSERT_EQ(oa, ob) << k->name << " orientation " << s.w << "x" << s.h;
			}
}

TEST(KernelEquality, ResampleRgb8)
{
	std::mt19937 rng(5);
	const std::pair<int, int> sizes[] = { { 1, 2 }, { 3, 6 }, { 5, 10 }, { 8, 12 }, { 13, 33 },
					      { 16, 40 }, { 7, 17 }, { 9, 9 }, { 20, 30 }, { 30, 20 },
					      { 13, 26 }, { 37, 74 } }; // 2x enlargements past one SIMD block
	for (const KernelTable *k : tablesUnderTest())
		for (auto [n, m] : sizes)
			for (auto [nh, mh] : sizes) {
				std::vector<ResampleTap> xt(m), yt(mh);
				if (!buildResampleTaps(n, m, 1.0, xt.data()) || !buildResampleTaps(nh, mh, 1.0, yt.data()))
					continue;
				const int srcStride = 3 * n + 2, dstStride = 3 * m + 1;
				const int offset = (n + nh) % 3; // 0, 1 or 2 bytes past an aligned start
				std::vector<uint8_t> src(size_t(srcStride) * nh + offset);
				for (auto &v : src)
					v = uint8_t(rng());
				std::vector<uint8_t> a(size_t(dstStride) * mh + offset, 5), b = a;
				std::vector<int32_t> row(3 * n + 8);
				resampleRgb8_ref(src.data() + offset, srcStride, n, nh, a.data() + offset, dstStride, m, mh, xt.data(), yt.data(), row.data());
				k->resampleRgb8(src.data() + offset, srcStride, n, nh, b.data() + offset, dstStride, m, mh, xt.data(), yt.data(), row.data());
				ASSERT_EQ(a, b) << k->name << " " << n << "x" << nh << " -> " << m << "x" << mh;
			}
}

TEST(KernelEquality, RgbToLuv)
{
	std::mt19937 rng(6);
	LuvTables t;
	buildLuvTables(t);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (int offset : { 0, 1 }) {
				const int rgbStride = 3 * s.w + 5, stride = s.w + 3;
				std::vector<uint8_t> rgb(size_t(rgbStride) * s.h + offset);
				for (auto &v : rgb)
					v = uint8_t(rng() % 4 == 0 ? (rng() % 2) * 255 : rng()); // extremes too
				std::vector<uint16_t> a(size_t(3) * stride * s.h + 1, 3), b = a;
				const size_t plane = size_t(stride) * s.h;
				rgbToLuv_ref(t, rgb.data() + offset, rgbStride, s.w, s.h, a.data(), a.data() + plane,
					     a.data() + 2 * plane, stride);
				k->rgbToLuv(t, rgb.data() + offset, rgbStride, s.w, s.h, b.data(), b.data() + plane,
					    b.data() + 2 * plane, stride);
				ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h;
			}
	// Every grey level and every pure colour ramp, where the ratios are extreme.
	for (const KernelTable *k : tablesUnderTest()) {
		std::vector<uint8_t> rgb(256 * 4 * 3);
		for (int i = 0; i < 256; i++)
			for (int c = 0; c < 3; c++) {
				rgb[3 * i + c] = uint8_t(i);
				for (int ramp = 0; ramp < 3; ramp++)
					rgb[3 * (256 * (ramp + 1) + i) + c] = c == ramp ? uint8_t(i) : 0;
			}
		std::vector<uint16_t> a(3 * 1024), b(3 * 1024);
		rgbToLuv_ref(t, rgb.data(), 0, 1024, 1, a.data(), a.data() + 1024, a.data() + 2048, 1024);
		k->rgbToLuv(t, rgb.data(), 0, 1024, 1, b.data(), b.data() + 1024, b.data() + 2048, 1024);
		ASSERT_EQ(a, b) << k->name << " ramps";
	}
}

TEST(KernelEquality, NormalizeMagnitude)
{
	std::mt19937 rng(7);
	for (double c : { 0.005, 0.0, 1e-7 }) { // the INRIA constant, and ones that need the scalar path
		GradientTables t;
		buildGradientTables(t, 6, 5, c);
		for (const KernelTable *k : tablesUnderTest())
			for (Size s : kSizes)
				for (int offset : { 0, 1 }) {
					const int stride = s.w + 1;
					auto magIn = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
					std::vector<uint32_t> sum(size_t(stride) * s.h + offset);
					for (size_t i = 0; i < sum.size(); i++)
						sum[i] = rng() % 3 == 0 ? rng() % 4096 : uint32_t(magIn[i]) * (1 + rng() % 1296);
					auto a = magIn, b = magIn;
					normalizeMag_ref(t, a.data() + offset, stride, sum.data() + offset, stride, s.w, s.h);
					k->normalizeMag(t, b.data() + offset, stride, sum.data() + offset, stride, s.w, s.h);
					ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h << " c " << c << " offset " << offset;
				}
	}
}

TEST(KernelEquality, OrientationHistograms)
{
	std::mt19937 rng(8);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (bool interpolate : { true, false })
				for (int nOrients : { 6, 1, 9 }) {
					const int stride = s.w + 3, w4 = s.w / 4, h4 = s.h / 4;
					const int offset = interpolate ? 1 : 0;
					auto mag = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
					auto orient = randomPlane(rng, size_t(stride) * s.h + offset, (nOrients << kOrientQ) - 1);
					const size_t plane = size_t(w4 + 1) * (h4 + 1);
					std::vector<uint16_t> ha(nOrients * plane + offset, 2), hb = ha;
					std::vector<uint16_t *> pa(nOrients), pb(nOrients);
					for (int o = 0; o < nOrients; o++) {
						pa[o] = ha.data() + offset + o * plane;
						pb[o] = hb.data() + offset + o * plane;
					}
					std::vector<uint32_t> scratch(nOrients * (s.w + 4));
					gradHist4_ref(mag.data() + offset, orient.data() + offset, stride, s.w, s.h, nOrients, interpolate, pa.data(), w4 + 1, scratch.data());
					k->gradHist4(mag.data() + offset, orient.data() + offset, stride, s.w, s.h, nOrients, interpolate, pb.data(), w4 + 1, scratch.data());
					ASSERT_EQ(ha, hb) << k->name << " " << s.w << "x" << s.h << " interpolate " << interpolate << " orientations " << nOrients;
				}
}

TEST(KernelEquality, Shrink4)
{
	std::mt19937 rng(9);
	for (const KernelTable *k : tablesUnderTest())
		for (Size s : kSizes)
			for (int extra : { 0, 2 }) {
				const int stride = s.w + 3, w4 = s.w / 4, h4 = s.h / 4, offset = extra ? 1 : 0;
				auto src = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
				std::vector<uint16_t> a(size_t(w4 + 2) * (h4 + 1) + offset, 4), b = a;
				std::vector<uint32_t> scratch(s.w + 4);
				shrink4_ref(src.data() + offset, stride, s.w, s.h, a.data() + offset, w4 + 2, extra, scratch.data());
				k->shrink4(src.data() + offset, stride, s.w, s.h, b.data() + offset, w4 + 2, extra, scratch.data());
				ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h << " extra shift " << extra;
			}
}
