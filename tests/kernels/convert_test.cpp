// SPDX-License-Identifier: BSD-2-Clause
// Camera pixel formats -> RGB8: the reference kernels' formulas (against the floating-point
// matrices, known values, exact cases of demosaicing), and every optimised conversion
// against the reference on odd sizes, padded strides, unaligned starts and strips.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels.h"

using namespace calped::kernels;

namespace {

std::vector<uint8_t> randomBytes(std::mt19937 &rng, size_t n)
{
	std::uniform_int_distribution<int> d(0, 255);
	std::vector<uint8_t> v(n);
	for (auto &x : v)
		x = uint8_t(d(rng));
	return v;
}

// One-pixel conversions through the reference 4:2:0 kernel.
void yuvToRgb(const YuvCoeffs &c, uint8_t y, uint8_t u, uint8_t v, uint8_t rgb[3])
{
	RawFrame f;
	f.planes[0] = &y;
	f.planes[1] = &u;
	f.planes[2] = &v;
	f.strides[0] = f.strides[1] = f.strides[2] = 1;
	f.width = f.height = 1;
	f.yuv = c;
	yuv420ToRgb8_ref(f, 0, 1, rgb, 3);
}

// The tables under test: every one besides the reference.
std::vector<const ConvertKernels *> tablesUnderTest()
{
	const ConvertKernels *all[8];
	const int n = availableConvertKernels(all, 8);
	return std::vector<const ConvertKernels *>(all + 1, all + n);
}

// A frame of random planes with `extra` bytes after each row and planes starting
// `offset` bytes into their buffers.
struct RandomFrame {
	std::vector<uint8_t> buffers[3];
	RawFrame f;
	RandomFrame(std::mt19937 &rng, int w, int h, const int rowBytes[3], const int rows[3],
		    int extra, int offset)
	{
		f.width = w;
		f.height = h;
		for (int i = 0; i < 3; i++) {
			if (!rowBytes[i])
				continue;
			f.strides[i] = rowBytes[i] + extra;
			buffers[i] = randomBytes(rng, size_t(f.strides[i]) * rows[i] + offset);
			f.planes[i] = buffers[i].data() + offset;
		}
	}
};

// Converts f whole with the reference and in strips of every height 1..5 starting at
// every row with `fn`, and requires identical rows.
void expectSameAsReference(ConvertRowsFn ref, ConvertRowsFn fn, const RawFrame &f,
			   const char *what)
{
	const ptrdiff_t stride = 3 * f.width + 5;
	std::vector<uint8_t> a(size_t(stride) * f.height, 7), b = a;
	ref(f, 0, f.height, a.data(), stride);
	fn(f, 0, f.height, b.data(), stride);
	ASSERT_EQ(a, b) << what << " " << f.width << "x" << f.height << " stride " << f.strides[0];
	for (int strip = 1; strip <= 5; strip++)
		for (int y0 = 0; y0 < f.height; y0 += strip) {
			const int rows = std::min(strip, f.height - y0);
			std::vector<uint8_t> s(size_t(stride) * rows, 7);
			fn(f, y0, rows, s.data(), stride);
			for (int y = 0; y < rows; y++)
				ASSERT_TRUE(std::equal(s.begin() + y * stride, s.begin() + y * stride + 3 * f.width,
						       a.begin() + (y0 + y) * stride))
					<< what << " " << f.width << "x" << f.height << " row " << y0 + y
					<< " of a strip of " << strip;
		}
}

const int kSizes[][2] = { { 2, 2 }, { 3, 2 }, { 2, 3 }, { 3, 3 }, { 5, 7 }, { 8, 8 },
			  { 13, 11 }, { 16, 17 }, { 31, 9 }, { 33, 40 }, { 67, 29 }, { 129, 21 } };

} // namespace

TEST(ConvertReference, YuvMatchesTheMatricesWithinOneStep)
{
	// Every encoding against the floating-point BT.601 / BT.709 matrices, on a grid of
	// Y, U, V: the Q8 coefficients are off by at most one 8-bit step.
	for (bool bt709 : { false, true })
		for (bool full : { false, true }) {
			const YuvCoeffs c = yuvCoeffs(bt709, full);
			const double kr = bt709 ? 0.2126 : 0.299, kb = bt709 ? 0.0722 : 0.114, kg = 1 - kr - kb;
			const double ys = full ? 1 : 255.0 / 219, cs = full ? 1 : 255.0 / 224;
			int worst = 0;
			for (int y = 0; y < 256; y += 3)
				for (int u = 0; u < 256; u += 5)
					for (int v = 0; v < 256; v += 5) {
						const double l = (y - (full ? 0 : 16)) * ys, d = (u - 128) * cs, e = (v - 128) * cs;
						const double want[3] = { l + 2 * (1 - kr) * e,
									 l - 2 * (1 - kb) * kb / kg * d - 2 * (1 - kr) * kr / kg * e,
									 l + 2 * (1 - kb) * d };
						uint8_t rgb[3];
						yuvToRgb(c, uint8_t(y), uint8_t(u), uint8_t(v), rgb);
						for (int k = 0; k < 3; k++) {
							const long r = std::lround(std::fmin(255, std::fmax(0, want[k])));
							worst = std::max(worst, int(std::labs(r - rgb[k])));
						}
					}
			EXPECT_LE(worst, 1) << (bt709 ? "BT.709" : "BT.601") << (full ? " full" : " limited");
		}
}

TEST(ConvertReference, YuvKnownValues)
{
	uint8_t rgb[3];
	const YuvCoeffs lim = yuvCoeffs(false, false), full = yuvCoeffs(false, true);
	yuvToRgb(lim, 16, 128, 128, rgb); // video black
	EXPECT_EQ(rgb[0] | rgb[1] | rgb[2], 0);
	yuvToRgb(lim, 235, 128, 128, rgb); // video white
	EXPECT_EQ(rgb[0] & rgb[1] & rgb[2], 255);
	yuvToRgb(lim, 0, 128, 128, rgb); // below black clamps
	EXPECT_EQ(rgb[0] | rgb[1] | rgb[2], 0);
	yuvToRgb(full, 100, 128, 128, rgb); // full-range grey is Y itself
	EXPECT_EQ(rgb[0], 100);
	EXPECT_EQ(rgb[1], 100);
	EXPECT_EQ(rgb[2], 100);
	// BT.601 limited red (Y 81, U 90, V 240): (255, 0, 0) within a step.
	yuvToRgb(lim, 81, 90, 240, rgb);
	EXPECT_GE(rgb[0], 254);
	EXPECT_LE(rgb[1], 1);
	EXPECT_LE(rgb[2], 1);
}

TEST(ConvertReference, ChromaIsCoSitedAndOddSizesUseTheLastSample)
{
	// 3x3 I420 with 2x2 chroma; NV12 of the same samples gives the same pixels.
	const uint8_t luma[9] = { 50, 60, 70, 80, 90, 100, 110, 120, 130 };
	const uint8_t u[4] = { 100, 150, 60, 200 }, v[4] = { 140, 90, 180, 30 };
	const uint8_t uv[8] = { 100, 140, 150, 90, 60, 180, 200, 30 };
	RawFrame i420;
	i420.planes[0] = luma;
	i420.planes[1] = u;
	i420.planes[2] = v;
	i420.strides[0] = 3;
	i420.strides[1] = i420.strides[2] = 2;
	i420.width = i420.height = 3;
	i420.yuv = yuvCoeffs(false, false);
	RawFrame nv12 = i420;
	nv12.planes[1] = uv;
	nv12.planes[2] = uv + 1;
	nv12.strides[1] = nv12.strides[2] = 4;
	nv12.chromaStep = 2;
	uint8_t a[27], b[27];
	yuv420ToRgb8_ref(i420, 0, 3, a, 9);
	yuv420ToRgb8_ref(nv12, 0, 3, b, 9);
	EXPECT_TRUE(std::equal(a, a + 27, b));
	for (int y = 0; y < 3; y++)
		for (int x = 0; x < 3; x++) {
			uint8_t want[3];
			const int c = (y / 2) * 2 + x / 2;
			yuvToRgb(i420.yuv, luma[3 * y + x], u[c], v[c], want);
			EXPECT_TRUE(std::equal(want, want + 3, a + 9 * y + 3 * x)) << x << "," << y;
		}
}

TEST(ConvertReference, YuyvPairsShareChroma)
{
	// 3 pixels: pairs (Y0 U Y1 V) (Y2 U' - V'); the third pixel uses the second pair.
	const uint8_t row[8] = { 60, 100, 200, 150, 120, 40, 0, 220 };
	RawFrame f;
	f.planes[0] = row;
	f.strides[0] = 8;
	f.width = 3;
	f.height = 1;
	f.yuv = yuvCoeffs(true, true);
	uint8_t out[9], want[3];
	yuyvToRgb8_ref(f, 0, 1, out, 9);
	const uint8_t expect[3][3] = { { 60, 100, 150 }, { 200, 100, 150 }, { 120, 40, 220 } };
	for (int x = 0; x < 3; x++) {
		yuvToRgb(f.yuv, expect[x][0], expect[x][1], expect[x][2], want);
		EXPECT_TRUE(std::equal(want, want + 3, out + 3 * x)) << "pixel " << x;
	}
}

TEST(ConvertReference, BgrAndGray)
{
	const uint8_t bgr[6] = { 1, 2, 3, 4, 5, 6 }, grey[2] = { 9, 250 };
	RawFrame f;
	f.planes[0] = bgr;
	f.strides[0] = 6;
	f.width = 2;
	f.height = 1;
	uint8_t out[6];
	bgr8ToRgb8_ref(f, 0, 1, out, 6);
	const uint8_t rgb[6] = { 3, 2, 1, 6, 5, 4 };
	EXPECT_TRUE(std::equal(out, out + 6, rgb));
	f.planes[0] = grey;
	gray8ToRgb8_ref(f, 0, 1, out, 6);
	const uint8_t greys[6] = { 9, 9, 9, 250, 250, 250 };
	EXPECT_TRUE(std::equal(out, out + 6, greys));
}

TEST(ConvertReference, BayerFlatColourAndInteriorRampsAreExact)
{
	// A mosaic of one colour demosaics to that colour everywhere (borders included: the
	// mirror keeps the pattern); a mosaic of per-channel linear ramps is exact inside.
	const int w = 11, h = 9;
	for (int redX : { 0, 1 })
		for (int redY : { 0, 1 }) {
			std::vector<uint8_t> flat(w * h), ramp(w * h), out(3 * w * h);
			auto channel = [&](int x, int y) {
				const bool rr = (y & 1) == redY, rc = (x & 1) == redX;
				return rr && rc ? 0 : (!rr && !rc ? 2 : 1);
			};
			const uint8_t colour[3] = { 200, 90, 30 };
			auto rampValue = [](int c, int x, int y) { return 20 + 7 * x + (3 + c) * y + 40 * c; };
			for (int y = 0; y < h; y++)
				for (int x = 0; x < w; x++) {
					flat[y * w + x] = colour[channel(x, y)];
					ramp[y * w + x] = uint8_t(rampValue(channel(x, y), x, y));
				}
			RawFrame f;
			f.planes[0] = flat.data();
			f.strides[0] = w;
			f.width = w;
			f.height = h;
			f.redX = redX;
			f.redY = redY;
			bayerToRgb8_ref(f, 0, h, out.data(), 3 * w);
			for (int i = 0; i < w * h; i++)
				for (int c = 0; c < 3; c++)
					ASSERT_EQ(out[3 * i + c], colour[c]) << "pixel " << i << " pattern " << redX << redY;
			f.planes[0] = ramp.data();
			bayerToRgb8_ref(f, 0, h, out.data(), 3 * w);
			for (int y = 1; y < h - 1; y++)
				for (int x = 1; x < w - 1; x++)
					for (int c = 0; c < 3; c++)
						ASSERT_EQ(out[3 * (y * w + x) + c], rampValue(c, x, y))
							<< x << "," << y << " channel " << c << " pattern " << redX << redY;
		}
}

TEST(ConvertEquality, Yuv420)
{
	std::mt19937 rng(11);
	for (const ConvertKernels *k : tablesUnderTest())
		for (auto s : kSizes)
			for (int nv12 : { 0, 1 })
				for (int extra : { 0, 3 }) {
					const int w = s[0], h = s[1], cw = (w + 1) / 2, ch = (h + 1) / 2;
					const int rowBytes[3] = { w, nv12 ? 2 * cw : cw, nv12 ? 0 : cw };
					const int rows[3] = { h, ch, ch };
					RandomFrame r(rng, w, h, rowBytes, rows, extra, extra ? 1 : 0);
					if (nv12) {
						r.f.planes[2] = r.f.planes[1] + 1;
						r.f.strides[2] = r.f.strides[1];
						r.f.chromaStep = 2;
					}
					for (int e = 0; e < 4; e++) {
						r.f.yuv = yuvCoeffs(e >= 2, e & 1);
						expectSameAsReference(yuv420ToRgb8_ref, k->yuv420, r.f, nv12 ? "NV12" : "I420");
					}
				}
}

TEST(ConvertEquality, Yuyv)
{
	std::mt19937 rng(12);
	for (const ConvertKernels *k : tablesUnderTest())
		for (auto s : kSizes)
			for (int extra : { 0, 5 }) {
				const int w = s[0], h = s[1];
				const int rowBytes[3] = { 4 * ((w + 1) / 2), 0, 0 }, rows[3] = { h, 0, 0 };
				RandomFrame r(rng, w, h, rowBytes, rows, extra, extra ? 3 : 0);
				for (int e = 0; e < 4; e++) {
					r.f.yuv = yuvCoeffs(e >= 2, e & 1);
					expectSameAsReference(yuyvToRgb8_ref, k->yuyv, r.f, "YUYV");
				}
			}
}

TEST(ConvertEquality, Bayer)
{
	std::mt19937 rng(13);
	for (const ConvertKernels *k : tablesUnderTest())
		for (auto s : kSizes)
			for (int extra : { 0, 1 })
				for (int pattern = 0; pattern < 4; pattern++) {
					const int w = s[0], h = s[1];
					const int rowBytes[3] = { w, 0, 0 }, rows[3] = { h, 0, 0 };
					RandomFrame r(rng, w, h, rowBytes, rows, extra, extra);
					r.f.redX = pattern & 1;
					r.f.redY = pattern >> 1;
					expectSameAsReference(bayerToRgb8_ref, k->bayer, r.f, "Bayer");
				}
}

TEST(ConvertEquality, BgrAndGray)
{
	std::mt19937 rng(14);
	for (const ConvertKernels *k : tablesUnderTest())
		for (auto s : kSizes) {
			const int w = s[0], h = s[1];
			const int bgrRow[3] = { 3 * w, 0, 0 }, greyRow[3] = { w, 0, 0 }, rows[3] = { h, 0, 0 };
			RandomFrame bgr(rng, w, h, bgrRow, rows, 2, 1), grey(rng, w, h, greyRow, rows, 2, 1);
			expectSameAsReference(bgr8ToRgb8_ref, k->bgr8, bgr.f, "BGR8");
			expectSameAsReference(gray8ToRgb8_ref, k->gray8, grey.f, "Gray8");
		}
}
