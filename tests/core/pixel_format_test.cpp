// SPDX-License-Identifier: BSD-2-Clause
// Every pixel format end to end through Detector::detect: BGR8 and grey give exactly the
// detections of the same pixels in RGB8; YUV and Bayer frames give exactly those of the
// RGB8 image the reference conversion makes of them (so the strip-wise, optimised path
// adds nothing), and close to those of the RGB frame they were encoded from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <calped/detector.h>

#include "input/frame_input.h"
#include "pixel_formats.h"
#include "synthetic.h"
#include "test_data.h"

using namespace calped;

namespace {

const PixelFormat kCameraFormats[] = { PixelFormat::NV12,       PixelFormat::YUV420,
				       PixelFormat::YUYV,       PixelFormat::BayerRGGB8,
				       PixelFormat::BayerGRBG8, PixelFormat::BayerGBRG8,
				       PixelFormat::BayerBGGR8 };

std::vector<Detection> detect(Detector &det, const ImageView &v)
{
	Detections d;
	const Status st = det.detect(v, d);
	EXPECT_TRUE(st.ok()) << pixelFormatName(v.format) << ": " << st.message();
	return std::vector<Detection>(d.begin(), d.end());
}

void expectIdentical(const std::vector<Detection> &a, const std::vector<Detection> &b,
		     const std::string &what)
{
	ASSERT_EQ(a.size(), b.size()) << what;
	for (size_t i = 0; i < a.size(); i++) {
		EXPECT_EQ(a[i].x, b[i].x) << what << " box " << i;
		EXPECT_EQ(a[i].y, b[i].y) << what << " box " << i;
		EXPECT_EQ(a[i].w, b[i].w) << what << " box " << i;
		EXPECT_EQ(a[i].h, b[i].h) << what << " box " << i;
		EXPECT_EQ(a[i].score, b[i].score) << what << " box " << i;
	}
}

// The RGB8 image the reference kernels make of a frame (whole, not in strips).
std::vector<uint8_t> referenceRgb(const ImageView &v)
{
	FrameInput in;
	EXPECT_TRUE(in.init(v.width, v.height, true, kernels::referenceConvertKernels()).ok());
	EXPECT_TRUE(checkImageLayout(v).ok());
	in.begin(v);
	ptrdiff_t stride;
	const uint8_t *rgb = in.wholeFrame(stride);
	EXPECT_EQ(stride, 3 * v.width);
	return std::vector<uint8_t>(rgb, rgb + size_t(stride) * v.height);
}

double iou(const Detection &a, const Detection &b)
{
	const double iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
	const double ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
	if (iw <= 0 || ih <= 0)
		return 0;
	return iw * ih / (double(a.w) * a.h + double(b.w) * b.h - iw * ih);
}

// Of the `from` boxes scoring >= minScore, how many have a `to` box at IoU >= 0.8; the
// relative score differences of the matches go to diffs.
struct Match {
	int considered = 0, matched = 0;
};
Match match(const std::vector<Detection> &from, const std::vector<Detection> &to, float minScore,
	    std::vector<double> &diffs)
{
	Match m;
	for (const Detection &a : from) {
		if (a.score < minScore)
			continue;
		m.considered++;
		const Detection *best = nullptr;
		double bestIou = 0;
		for (const Detection &b : to)
			if (iou(a, b) > bestIou) {
				bestIou = iou(a, b);
				best = &b;
			}
		if (best && bestIou >= 0.8) {
			m.matched++;
			diffs.push_back(std::fabs(best->score - a.score) / std::fabs(a.score));
		}
	}
	return m;
}

std::unique_ptr<Detector> syntheticDetector(double resize)
{
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.resize = resize;
	cfg.cascadeThreshold = -10.0f; // many windows pass: detections are sensitive to pixels
	std::unique_ptr<Detector> det;
	EXPECT_TRUE(Detector::create(test::randomModel(7, 512), cfg, det).ok());
	return det;
}

std::unique_ptr<Detector> petsDetector(double resize)
{
	const std::string blobPath = test::inriaModelBlob();
	if (blobPath.empty() || test::petsFrame(1).empty())
		return nullptr;
	std::vector<uint8_t> blob;
	Model model;
	if (!test::readFile(blobPath, blob) || !loadModel(blob.data(), blob.size(), model).ok())
		return nullptr;
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = resize;
	std::unique_ptr<Detector> det;
	EXPECT_TRUE(Detector::create(model, cfg, det).ok());
	return det;
}

// BGR8 and Gray8 against RGB8 of the same pixels, exactly; padded rows throughout.
void expectBgrAndGreyExact(Detector &det, const uint8_t *rgb, int w, int h, const char *what)
{
	const auto rgbDets = detect(det, ImageView::rgb8(rgb, w, h));
	EXPECT_GT(rgbDets.size(), 0u) << what;
	const auto bgr = test::encodeImage(rgb, w, h, PixelFormat::BGR8, YuvEncoding::Bt601Limited, 5);
	expectIdentical(detect(det, bgr.view()), rgbDets, std::string(what) + " BGR8");
	const auto grey = test::greyRgb(rgb, w, h);
	const auto greyDets = detect(det, ImageView::rgb8(grey.data(), w, h));
	const auto gray8 = test::encodeImage(rgb, w, h, PixelFormat::Gray8, YuvEncoding::Bt601Limited, 3);
	expectIdentical(detect(det, gray8.view()), greyDets, std::string(what) + " Gray8");
}

} // namespace

TEST(PixelFormats, BgrAndGreyMatchRgbExactlySynthetic)
{
	for (double resize : { 1.0, 2.0 }) {
		auto det = syntheticDetector(resize);
		for (auto [w, h] : { std::pair{ 320, 240 }, { 201, 153 } }) {
			const auto img = test::randomImage(21, w, h);
			expectBgrAndGreyExact(*det, img.data(), w, h, resize == 1.0 ? "resize 1" : "resize 2");
		}
	}
}

TEST(PixelFormats, CameraFormatsMatchTheirReferenceConversionSynthetic)
{
	// Odd sizes (half chroma samples, Bayer borders on odd rows), padded planes, every
	// YUV encoding, both input paths (strips at resize 1, whole frame at resize 2).
	for (double resize : { 1.0, 2.0 }) {
		auto det = syntheticDetector(resize);
		for (auto [w, h] : { std::pair{ 320, 240 }, { 201, 153 } }) {
			if (resize != 1.0 && w == 320)
				continue; // the whole-frame path once, at the odd size (keeps the test short)
			const auto img = test::randomImage(22, w, h);
			for (PixelFormat f : kCameraFormats)
				for (int e = 0; e < 4; e++) {
					const YuvEncoding enc = YuvEncoding(e);
					if (e > 0 && (f != PixelFormat::NV12 && f != PixelFormat::YUYV))
						continue;
					const auto frame = test::encodeImage(img.data(), w, h, f, enc, 7);
					const auto rgb = referenceRgb(frame.view());
					const auto want = detect(*det, ImageView::rgb8(rgb.data(), w, h));
					EXPECT_GT(want.size(), 0u);
					char what[96];
					std::snprintf(what, sizeof what, "%s encoding %d %dx%d resize %g",
						      pixelFormatName(f), e, w, h, resize);
					expectIdentical(detect(*det, frame.view()), want, what);
				}
		}
	}
}

TEST(PixelFormats, PetsFramesInEveryFormat)
{
	auto det = petsDetector(1.0);
	if (!det)
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	const int kFrames = 10;
	const int n = int(sizeof kCameraFormats / sizeof kCameraFormats[0]);
	std::vector<Match> there(n), back(n);
	std::vector<std::vector<double>> diffs(n);
	std::vector<double> pixelError(n);
	for (int k = 1; k <= kFrames; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		const int w = img.width, h = img.height;
		const uint8_t *rgb = img.pixels.data();
		if (k == 1)
			expectBgrAndGreyExact(*det, rgb, w, h, "PETS");
		const auto original = detect(*det, ImageView::rgb8(rgb, w, h));
		for (int i = 0; i < n; i++) {
			const PixelFormat f = kCameraFormats[i];
			const auto frame = test::encodeImage(rgb, w, h, f, YuvEncoding::Bt601Limited, 16);
			const auto converted = referenceRgb(frame.view());
			const auto want = detect(*det, ImageView::rgb8(converted.data(), w, h));
			const auto got = detect(*det, frame.view());
			expectIdentical(got, want, std::string("PETS ") + pixelFormatName(f));
			const Match a = match(original, got, 10.0f, diffs[i]);
			const Match b = match(got, original, 10.0f, diffs[i]);
			there[i].considered += a.considered;
			there[i].matched += a.matched;
			back[i].considered += b.considered;
			back[i].matched += b.matched;
			double sum = 0;
			for (size_t p = 0; p < converted.size(); p++)
				sum += std::abs(int(converted[p]) - int(rgb[p]));
			pixelError[i] += sum / converted.size() / kFrames;
		}
	}
	// Close to the RGB frame they were encoded from. Measured on frames 1-10 (IoU >= 0.8,
	// scores >= 10): YUV found 30/30 RGB boxes and 32/33 of its own were in RGB, median
	// score difference 4.8-7.2%, mean pixel error 0.33-0.35; Bayer (bilinear demosaicing
	// blurs colour edges and leaves zipper artefacts that change the gradient channels)
	// found 21-25/30 and 24-29 of 32-40, median score difference 11-17%, pixel error 2.65.
	// The bounds below leave room for that, and fail if a conversion goes wrong (a swapped
	// channel or a misplaced chroma sample costs far more).
	for (int i = 0; i < n; i++) {
		const PixelFormat f = kCameraFormats[i];
		std::sort(diffs[i].begin(), diffs[i].end());
		const double median = diffs[i].empty() ? 1.0 : diffs[i][diffs[i].size() / 2];
		const double found = there[i].matched / std::max(1.0, double(there[i].considered));
		const double foundBack = back[i].matched / std::max(1.0, double(back[i].considered));
		std::printf("PETS 1-%d %-10s: mean |pixel - RGB| %.2f; RGB boxes >= 10 found %d/%d, "
			    "its boxes >= 10 in RGB %d/%d, median relative score difference %.2f%%\n",
			    kFrames, pixelFormatName(f), pixelError[i], there[i].matched,
			    there[i].considered, back[i].matched, back[i].considered, 100 * median);
		EXPECT_GT(there[i].considered, 0);
		const bool bayer = f != PixelFormat::NV12 && f != PixelFormat::YUV420 && f != PixelFormat::YUYV;
		EXPECT_GE(found, bayer ? 0.6 : 0.95) << pixelFormatName(f);
		EXPECT_GE(foundBack, bayer ? 0.55 : 0.9) << pixelFormatName(f);
		EXPECT_LE(median, bayer ? 0.25 : 0.1) << pixelFormatName(f);
		EXPECT_LE(pixelError[i], bayer ? 4.0 : 0.6) << pixelFormatName(f);
	}
}
