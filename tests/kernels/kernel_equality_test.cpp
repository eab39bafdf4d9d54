// SPDX-License-Identifier: BSD-2-Clause
// Every optimised kernel against the scalar reference: random inputs, odd widths and
// heights, strides wider than rows and unaligned starts (base pointers one element past an
// aligned address, for inputs and outputs); outputs must be bit-identical.
// The colour conversion and the magnitude normalisation have no portable optimised
// version (the "opt" table holds their references), so on a build or CPU without SIMD
// kernels nothing would be compared: every table's, the reference's included, is also
// checked against the toolbox's formula worked out here in double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// Every table, the reference first.
std::vector<const KernelTable *> allTables()
{
	const KernelTable *all[8];
	const int n = availableKernelTables(all, 8);
	return std::vector<const KernelTable *>(all, all + n);
}

// ---- the toolbox's formulas, in double precision ---------------------------------------
// From docs/channels.md and the toolbox's constants (rgbConvertMex's matrix, u'n, v'n),
// written independently of lib/kernels/tables.cpp: a wrong table entry or constant, or a
// kernel that reads them wrongly, shows up here on every build.

// The toolbox's rcpps on the Intel CPU of the reference (docs/channels.md): v's mantissa in
// [1, 2) cut to its top 11 fraction bits, 1 / x taken at the middle of that cell and
// rounded to nearest with 12 fraction bits (of its own mantissa, in (1, 2]).
double rcppsIntel(double v)
{
	const int e = std::ilogb(v);                  // v = mant * 2^e, mant in [1, 2)
	const double mant = std::scalbn(v, -e);
	const double cell = std::floor((mant - 1) * 2048);
	const double mid = 1 + (cell + 0.5) / 2048;
	const double inv2 = 2 / mid;                  // in (1, 2]: 1 / mid = inv2 / 2
	return std::scalbn(std::nearbyint(inv2 * 4096) / 4096, -e - 1);
}

// CIE lightness over 270 of a luminance y in [0, 1], as the toolbox tabulates it.
double lightnessOver270(double y)
{
	const double y0 = std::pow(6.0 / 29.0, 3.0);
	return (y > y0 ? 116 * std::cbrt(y) - 16 : y * std::pow(29.0 / 3.0, 3.0)) / 270;
}

// rgbConvert(I, 'luv') of one 8-bit pixel in Q16 (value * 2^16, not rounded): the sRGB ->
// XYZ matrix of the toolbox's rgbConvertMex; L from its 1025-entry table indexed by
// floor(y * 1024), held in Q16 (rounded, kernels.h); u = L (52 x / d - 13 u'n) + 88/270
// and v = L (117 y / d - 13 v'n) + 134/270 with d = x + 15 y + 3 z and 1 / d by rcpps.
// `nudge` moves y * 1024 and d by a relative 1e-6 before they are cut (the kernel's Q28
// sums differ from exact ones by less): a pixel whose table index or reciprocal cell
// lies that close to an edge may take either side.
struct Luv {
	double l, u, v;
};
Luv luvFormula(const uint8_t *rgb, int nudge)
{
	const double r = rgb[0] / 255.0, g = rgb[1] / 255.0, b = rgb[2] / 255.0;
	const double x = 0.430574 * r + 0.341550 * g + 0.178325 * b;
	const double y = 0.222015 * r + 0.706655 * g + 0.071330 * b;
	const double z = 0.020183 * r + 0.129553 * g + 0.939180 * b;
	const double k = 1 + nudge * 1e-6;
	const double index = std::min(std::floor(y * 1024 * k), 1024.0);
	const double l = std::nearbyint(lightnessOver270(index / 1024) * 65536) / 65536;
	const double d = x + 15 * y + 3 * z;
	const double rd = d > 0 ? rcppsIntel(d * k) : 0;
	const double u = l * (52 * x * rd - 13 * 0.197833) + 88.0 / 270;
	const double v = l * (117 * y * rd - 13 * 0.468331) + 134.0 / 270;
	return { l * 65536, u * 65536, v * 65536 };
}

double saturate16(double q) { return std::min(std::max(q, 0.0), 65535.0); }

// A kernel's L, U and V of one pixel against luvFormula: L exactly, U and V within
// kLuvTolerance. The bound, in Q16 units: the x/d and y/d ratios are rounded to Q20, then
// multiplied by 52 or 117 and by L <= 0.371 (V: 117 * 0.371 * 2^-21 * 2^16 = 1.4); the
// Q28 matrix entries are rounded (3 * 0.5 * 255 * 2^-28 in x, y, z: 0.3 in V); 13 u'n and
// 13 v'n are Q20 (0.01); the offset and the result are rounded (0.5 each): 2.7 in all.
// The largest seen: 2.0-2.3 (V of RGB 231,235,233 is 2.04 off).
constexpr double kLuvTolerance = 3;
::testing::AssertionResult luvMatchesFormula(const uint8_t *rgb, uint16_t l, uint16_t u,
					     uint16_t v)
{
	for (int nudge : { 0, -1, 1 }) {
		const Luv want = luvFormula(rgb, nudge);
		if (l == want.l && std::fabs(u - saturate16(want.u)) <= kLuvTolerance &&
		    std::fabs(v - saturate16(want.v)) <= kLuvTolerance)
			return ::testing::AssertionSuccess();
	}
	const Luv want = luvFormula(rgb, 0);
	return ::testing::AssertionFailure()
	       << "RGB " << int(rgb[0]) << "," << int(rgb[1]) << "," << int(rgb[2]) << ": got L "
	       << l << " U " << u << " V " << v << ", the toolbox's formula gives L " << want.l
	       << " U " << saturate16(want.u) << " V " << saturate16(want.v) << " (U, V within "
	       << kLuvTolerance << ")";
}

// gradMagNorm of one pixel in Q14: M / (S / (r+1)^4 + c) with M the Q16 magnitude and S
// the triangle filter's sum of Q16 magnitudes (weights summing to (r+1)^4), so that
// M / (S / (r+1)^4 + c) = M (r+1)^4 / (S + c 2^16 (r+1)^4) =: M (r+1)^4 / D. The divisor D
// is an integer (the constant rounded to one), divided by rcpps as the toolbox divides
// (docs/channels.md); D = 0 (no magnitude, c = 0) gives 0. Saturated at 65535.
double normalizedFormula(uint16_t mag, uint32_t sum, int normRad, double normConst)
{
	const double weights = std::pow(normRad + 1.0, 4.0);
	const double D = double(sum) + std::nearbyint(normConst * 65536 * weights);
	if (D == 0)
		return 0;
	return std::min(65535.0, mag * weights * 16384 * rcppsIntel(D));
}

// Bound for normalizeMag against the formula, Q14 units: the kernel's reciprocal table
// holds (r+1)^4 2^16 rcpps(m) rounded to an integer (relative error <= 0.5 / 20736 at
// r = 5, times at most 65535: 1.6), and the result is rounded (0.5): 2.1.
constexpr double kNormTolerance = 2.5;

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
		EXPECT_STREQ(bestConvertKernels().name, "neon"); // the pixel-format conversions too
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
	// Both CPUs' reciprocal tables: the kernels index them by the same 12 fraction bits.
	for (RcpRule rule : { RcpRule::Intel, RcpRule::AmdEpyc }) {
		LuvTables t;
		buildLuvTables(t, rule);
		// Every table's kernel against the formula; those with a kernel of their own (not the
		// reference's) also bit for bit against the reference.
		for (const KernelTable *k : allTables()) {
			const bool own = k->rgbToLuv != rgbToLuv_ref;
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
					if (own) {
						ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h;
					}
					// The formula is Intel's rcpps; AMD's table only against the reference.
					for (int y = 0; rule == RcpRule::Intel && y < s.h; y++)
						for (int x = 0; x < s.w; x++) {
							const size_t o = size_t(y) * stride + x;
							ASSERT_TRUE(luvMatchesFormula(&rgb[offset + size_t(y) * rgbStride + 3 * x], b[o],
										      b[plane + o], b[2 * plane + o]))
								<< k->name << " " << s.w << "x" << s.h << " pixel " << x << "," << y;
						}
				}
		}
		// Every grey level and every pure colour ramp, where the ratios are extreme, and a
		// lattice of the colour cube (every fifth level of each component, ends included).
		std::vector<uint8_t> rgb(256 * 4 * 3);
		for (int i = 0; i < 256; i++)
			for (int c = 0; c < 3; c++) {
				rgb[3 * i + c] = uint8_t(i);
				for (int ramp = 0; ramp < 3; ramp++)
					rgb[3 * (256 * (ramp + 1) + i) + c] = c == ramp ? uint8_t(i) : 0;
			}
		for (int r = 0; r <= 255; r += 5)
			for (int g = 0; g <= 255; g += 5)
				for (int b = 0; b <= 255; b += 5)
					rgb.insert(rgb.end(), { uint8_t(r), uint8_t(g), uint8_t(b) });
		const int n = int(rgb.size() / 3);
		std::vector<uint16_t> a(3 * size_t(n));
		rgbToLuv_ref(t, rgb.data(), 0, n, 1, a.data(), a.data() + n, a.data() + 2 * n, n);
		for (const KernelTable *k : allTables()) {
			std::vector<uint16_t> b(3 * size_t(n));
			k->rgbToLuv(t, rgb.data(), 0, n, 1, b.data(), b.data() + n, b.data() + 2 * n, n);
			if (k->rgbToLuv != rgbToLuv_ref) {
				ASSERT_EQ(a, b) << k->name << " ramps and lattice";
			}
			for (int i = 0; rule == RcpRule::Intel && i < n; i++)
				ASSERT_TRUE(luvMatchesFormula(&rgb[3 * size_t(i)], b[i], b[n + i], b[2 * n + i]))
					<< k->name << " ramps and lattice, pixel " << i;
		}
	}
}

TEST(KernelEquality, NormalizeMagnitude)
{
	std::mt19937 rng(7);
	const int normRad = 5;
	for (double c : { 0.005, 0.0, 1e-7 }) { // the INRIA constant, and ones that need the scalar path
		GradientTables t;
		buildGradientTables(t, 6, normRad, c);
		for (const KernelTable *k : allTables()) {
			const bool own = k->normalizeMag != normalizeMag_ref;
			for (Size s : kSizes)
				for (int offset : { 0, 1 }) {
					const int stride = s.w + 1;
					auto magIn = randomPlane(rng, size_t(stride) * s.h + offset, 65535);
					std::vector<uint32_t> sum(size_t(stride) * s.h + offset);
					for (size_t i = 0; i < sum.size(); i++)
						sum[i] = rng() % 3 == 0 ? rng() % 4096 : uint32_t(magIn[i]) * (1 + rng() % 1296);
					if (s.w * s.h > 8)
						sum[offset] = 0; // no magnitude around: D is the constant alone, or 0
					auto a = magIn, b = magIn;
					normalizeMag_ref(t, a.data() + offset, stride, sum.data() + offset, stride, s.w, s.h);
					k->normalizeMag(t, b.data() + offset, stride, sum.data() + offset, stride, s.w, s.h);
					if (own) {
						ASSERT_EQ(a, b) << k->name << " " << s.w << "x" << s.h << " c " << c << " offset " << offset;
					}
					for (int y = 0; y < s.h; y++)
						for (int x = 0; x < s.w; x++) {
							const size_t i = offset + size_t(y) * stride + x;
							const double want = normalizedFormula(magIn[i], sum[i], normRad, c);
							ASSERT_LE(std::fabs(b[i] - want), kNormTolerance)
								<< k->name << " c " << c << ": M " << magIn[i] << ", S " << sum[i]
								<< " gave " << b[i] << ", the toolbox's formula " << want;
						}
					// Outside the rectangle nothing changed.
					for (int y = 0; y < s.h; y++)
						ASSERT_EQ(b[offset + size_t(y) * stride + s.w], magIn[offset + size_t(y) * stride + s.w]);
				}
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
