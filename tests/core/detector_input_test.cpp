// SPDX-License-Identifier: BSD-2-Clause
// Bad frames and bad configurations get a documented error, and the detector keeps
// working afterwards.
#include <string>
#include <gtest/gtest.h>

#include <calped/detector.h>

#include "pixel_formats.h"
#include "synthetic.h"

using namespace calped;

namespace {

std::unique_ptr<Detector> makeDetector(double resize = 1.0)
{
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.resize = resize;
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(test::randomModel(3), cfg, det);
	EXPECT_TRUE(st.ok()) << st.message();
	return det;
}

// The detector still runs on a good frame after a failure.
void expectHealthy(Detector &det)
{
	const auto img = test::randomImage(1, 320, 240);
	Detections d;
	const Status st = det.detect(ImageView::rgb8(img.data(), 320, 240), d);
	EXPECT_TRUE(st.ok()) << st.message();
	EXPECT_GT(det.lastStats().windows, 0u);
}

ErrorCode detectCode(Detector &det, const ImageView &v)
{
	Detections d;
	const Status st = det.detect(v, d);
	EXPECT_EQ(d.count, 0);
	if (!st.ok()) {
		EXPECT_NE(std::string(st.message()).find(errorCodeName(st.code())), std::string::npos)
			<< "message names its error: " << st.message();
	}
	return st.code();
}

} // namespace

TEST(DetectorInput, EmptyImages)
{
	auto det = makeDetector();
	const auto img = test::randomImage(1, 320, 240);
	EXPECT_EQ(detectCode(*det, ImageView::rgb8(img.data(), 0, 0)), ErrorCode::ImageEmpty);
	EXPECT_EQ(detectCode(*det, ImageView::rgb8(img.data(), 0, 240)), ErrorCode::ImageEmpty);
	EXPECT_EQ(detectCode(*det, ImageView::rgb8(nullptr, 320, 240)), ErrorCode::ImageEmpty);
	expectHealthy(*det);
}

TEST(DetectorInput, TooSmallForTheModel)
{
	for (double resize : { 1.0, 2.0 }) {
		auto det = makeDetector(resize);
		// Sizes that, once resized, are narrower than 41 or lower than 100 pixels.
		const int k = int(resize);
		for (auto [w, h] : { std::pair{ 1, 1 }, { 2, 3 }, { 40 / k, 99 / k }, { 40 / k, 240 },
				     { 320, 99 / k } }) {
			const auto img = test::randomImage(2, w, h);
			const ErrorCode code = detectCode(*det, ImageView::rgb8(img.data(), w, h));
			EXPECT_EQ(code, ErrorCode::ImageTooSmall) << w << "x" << h << " resize " << resize;
		}
		expectHealthy(*det);
	}
}

TEST(DetectorInput, OddSizesRun)
{
	auto det = makeDetector();
	for (auto [w, h] : { std::pair{ 41, 100 }, { 43, 101 }, { 127, 131 }, { 319, 239 }, { 257, 233 } }) {
		const auto img = test::randomImage(3, w, h);
		Detections d;
		const Status st = det->detect(ImageView::rgb8(img.data(), w, h), d);
		EXPECT_TRUE(st.ok()) << w << "x" << h << ": " << st.message();
		EXPECT_GE(det->lastStats().levels, 1) << w << "x" << h;
	}
	expectHealthy(*det);
}

TEST(DetectorInput, FrameSizesMayAlternate)
{
	// Resampling taps are prepared for maximum-size frames and built per frame for the
	// others: alternating sizes must give every frame the detections a fresh detector
	// gives it, with and without an input resize.
	for (double resize : { 1.0, 1.5 }) {
		SCOPED_TRACE(resize);
		DetectorConfig cfg;
		cfg.maxWidth = 320;
		cfg.maxHeight = 240;
		cfg.resize = resize;
		cfg.cascadeThreshold = -10.0f; // many windows pass: the detections say a lot
		const Model model = test::randomModel(5);
		std::unique_ptr<Detector> shared;
		ASSERT_TRUE(Detector::create(model, cfg, shared).ok());
		const std::pair<int, int> sizes[] = { { 320, 240 }, { 257, 233 }, { 320, 240 }, { 300, 240 }, { 320, 240 } };
		for (auto [w, h] : sizes) {
			SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
			const auto img = test::randomImage(uint32_t(w + h), w, h);
			std::unique_ptr<Detector> fresh;
			ASSERT_TRUE(Detector::create(model, cfg, fresh).ok());
			Detections a, b;
			ASSERT_TRUE(shared->detect(ImageView::rgb8(img.data(), w, h), a).ok());
			ASSERT_TRUE(fresh->detect(ImageView::rgb8(img.data(), w, h), b).ok());
			ASSERT_EQ(a.count, b.count);
			ASSERT_GT(a.count, 0);
			for (int i = 0; i < a.count; i++) {
				EXPECT_EQ(a.items[i].x, b.items[i].x);
				EXPECT_EQ(a.items[i].y, b.items[i].y);
				EXPECT_EQ(a.items[i].h, b.items[i].h);
				EXPECT_EQ(a.items[i].score, b.items[i].score);
			}
		}
	}
}

TEST(DetectorInput, SmallerFramesGiveWhatADetectorOfTheirSizeGives)
{
	// A frame smaller than the configured maximum has its resampling taps built per frame;
	// a detector configured for exactly its size uses the cached ones. With different
	// lambdas for magnitude and histograms (Caltech+ has 0.110 and 0.108) each channel type
	// must get its own gain on both paths.
	Model model = test::randomModel(7);
	model.params.lambdas[1] = 0.25f;
	model.params.lambdas[2] = 0.02f;
	const int w = 257, h = 233;
	const auto img = test::randomImage(11, w, h);
	for (double resize : { 1.0, 1.5 }) {
		SCOPED_TRACE(resize);
		DetectorConfig larger;
		larger.maxWidth = 320;
		larger.maxHeight = 240;
		larger.resize = resize;
		larger.cascadeThreshold = -10.0f; // many windows pass: the scores say a lot
		DetectorConfig exact = larger;
		exact.maxWidth = w;
		exact.maxHeight = h;
		std::unique_ptr<Detector> a, b;
		ASSERT_TRUE(Detector::create(model, larger, a).ok());
		ASSERT_TRUE(Detector::create(model, exact, b).ok());
		Detections da, db;
		ASSERT_TRUE(a->detect(ImageView::rgb8(img.data(), w, h), da).ok());
		ASSERT_TRUE(b->detect(ImageView::rgb8(img.data(), w, h), db).ok());
		ASSERT_GT(da.count, 0);
		ASSERT_EQ(da.count, db.count);
		for (int i = 0; i < da.count; i++) {
			EXPECT_EQ(da.items[i].x, db.items[i].x);
			EXPECT_EQ(da.items[i].y, db.items[i].y);
			EXPECT_EQ(da.items[i].score, db.items[i].score);
		}
	}
}

TEST(DetectorInput, LargerThanConfigured)
{
	auto det = makeDetector();
	const auto img = test::randomImage(4, 321, 240);
	EXPECT_EQ(detectCode(*det, ImageView::rgb8(img.data(), 321, 240)), ErrorCode::ImageTooLarge);
	expectHealthy(*det);
}

TEST(DetectorInput, WrongFormatAndStride)
{
	auto det = makeDetector();
	const auto img = test::randomImage(5, 320, 240);
	ImageView v = ImageView::rgb8(img.data(), 320, 240);
	v.format = PixelFormat(99);
	EXPECT_EQ(detectCode(*det, v), ErrorCode::UnsupportedPixelFormat);
	EXPECT_EQ(detectCode(*det, ImageView::rgb8(img.data(), 320, 240, 100)), ErrorCode::InvalidArgument);
	expectHealthy(*det);
}

// Expects `code` and a message naming the format.
void expectRejected(Detector &det, const ImageView &v, ErrorCode code, const char *what)
{
	Detections d;
	const Status st = det.detect(v, d);
	EXPECT_EQ(st.code(), code) << pixelFormatName(v.format) << " " << what << ": " << st.message();
	EXPECT_NE(std::string(st.message()).find(pixelFormatName(v.format)), std::string::npos)
		<< "message names the format: " << st.message();
	EXPECT_EQ(d.count, 0);
}

TEST(DetectorInput, BadFramesOfEveryFormat)
{
	auto det = makeDetector();
	const int w = 121, h = 131; // odd: chroma planes have 61 x 66 samples
	const auto rgb = test::randomImage(8, w, h);
	const PixelFormat formats[] = { PixelFormat::RGB8,       PixelFormat::BGR8,
					PixelFormat::Gray8,      PixelFormat::NV12,
					PixelFormat::YUV420,     PixelFormat::YUYV,
					PixelFormat::BayerRGGB8, PixelFormat::BayerGRBG8,
					PixelFormat::BayerGBRG8, PixelFormat::BayerBGGR8 };
	for (PixelFormat f : formats) {
		const auto frame = test::encodeImage(rgb.data(), w, h, f);
		const ImageView good = frame.view();
		Detections d;
		const Status ok = det->detect(good, d);
		EXPECT_TRUE(ok.ok()) << pixelFormatName(f) << ": " << ok.message();
		const int planes = f == PixelFormat::YUV420 ? 3 : (f == PixelFormat::NV12 ? 2 : 1);
		for (int i = 0; i < planes; i++) {
			ImageView v = good;
			v.planes[i] = nullptr;
			expectRejected(*det, v, ErrorCode::ImageEmpty, "null plane");
			v = good;
			v.strides[i] -= 1; // one byte short of a row
			expectRejected(*det, v, ErrorCode::InvalidArgument, "short stride");
			v.strides[i] = -good.strides[i];
			expectRejected(*det, v, ErrorCode::InvalidArgument, "negative stride");
		}
		ImageView v = good;
		v.width = 0;
		expectRejected(*det, v, ErrorCode::ImageEmpty, "zero width");
		v = good;
		v.height = -3;
		expectRejected(*det, v, ErrorCode::ImageEmpty, "negative height");
		const auto wide = test::randomImage(8, 321, 20);
		const auto tooWide = test::encodeImage(wide.data(), 321, 20, f);
		expectRejected(*det, tooWide.view(), ErrorCode::ImageTooLarge, "too wide");
		if (f == PixelFormat::NV12 || f == PixelFormat::YUV420 || f == PixelFormat::YUYV) {
			v = good;
			v.yuv = YuvEncoding(7);
			expectRejected(*det, v, ErrorCode::InvalidArgument, "unknown encoding");
		}
		if (planes == 1 && f >= PixelFormat::BayerRGGB8) {
			v = good;
			v.width = 1;
			expectRejected(*det, v, ErrorCode::ImageTooSmall, "1-pixel Bayer");
		}
	}
	expectHealthy(*det);
}

TEST(DetectorInput, StrideIsHonoured)
{
	// The same pixels packed and inside wider rows give the same detections.
	auto det = makeDetector();
	const int w = 200, h = 150, stride = 3 * w + 37;
	const auto packed = test::randomImage(6, w, h);
	std::vector<uint8_t> padded(size_t(stride) * h, 0xAB);
	for (int y = 0; y < h; y++)
		std::copy(packed.begin() + size_t(y) * 3 * w, packed.begin() + size_t(y + 1) * 3 * w,
			  padded.begin() + size_t(y) * stride);
	Detections a, b;
	ASSERT_TRUE(det->detect(ImageView::rgb8(packed.data(), w, h), a).ok());
	std::vector<Detection> first(a.begin(), a.end());
	ASSERT_TRUE(det->detect(ImageView::rgb8(padded.data(), w, h, stride), b).ok());
	ASSERT_EQ(first.size(), size_t(b.count));
	for (int i = 0; i < b.count; i++) {
		EXPECT_EQ(first[i].x, b.items[i].x);
		EXPECT_EQ(first[i].score, b.items[i].score);
	}
}

TEST(DetectorInput, BadConfigurations)
{
	const Model model = test::randomModel(3);
	std::unique_ptr<Detector> det;
	DetectorConfig cfg;
	cfg.maxWidth = 0;
	EXPECT_EQ(Detector::create(model, cfg, det).code(), ErrorCode::InvalidArgument);
	cfg = DetectorConfig();
	cfg.resize = 0;
	EXPECT_EQ(Detector::create(model, cfg, det).code(), ErrorCode::InvalidArgument);
	cfg.resize = 100;
	EXPECT_EQ(Detector::create(model, cfg, det).code(), ErrorCode::InvalidArgument);
	cfg.resize = 0.5; // the pyramid only upscales (the default resizeAt)
	const Status down = Detector::create(model, cfg, det);
	EXPECT_EQ(down.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(down.message()).find("pyramid"), std::string::npos) << down.message();
	cfg = DetectorConfig();
	cfg.maxCandidates = 0;
	EXPECT_EQ(Detector::create(model, cfg, det).code(), ErrorCode::InvalidArgument);
	EXPECT_EQ(det, nullptr);
	Model broken = model;
	broken.fids[0] = 1u << 30;
	EXPECT_EQ(Detector::create(broken, DetectorConfig(), det).code(), ErrorCode::ModelInvalid);
}

TEST(DetectorInput, FramesBeyondTheResamplerAreRefusedAtCreate)
{
	// So large that a pyramid level would have to be resampled more than 10x smaller in
	// one step: create() says so, rather than detect() failing on every frame.
	DetectorConfig cfg;
	cfg.maxWidth = 4000;
	cfg.maxHeight = 4000;
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(test::randomModel(3), cfg, det);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("resampler"), std::string::npos) << st.message();
	EXPECT_EQ(det, nullptr);
}

TEST(DetectorInput, CandidateOverflowIsCounted)
{
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.maxCandidates = 5;
	cfg.cascadeThreshold = -30000.0f; // every window passes
	cfg.nms = false;
	std::unique_ptr<Detector> det;
	ASSERT_TRUE(Detector::create(test::randomModel(3), cfg, det).ok());
	const auto img = test::randomImage(1, 320, 240);
	Detections d;
	ASSERT_TRUE(det->detect(ImageView::rgb8(img.data(), 320, 240), d).ok());
	const FrameStats &s = det->lastStats();
	EXPECT_EQ(d.count, 5);
	EXPECT_EQ(s.candidates, s.windows);
	EXPECT_EQ(s.droppedWindows, s.windows - 5);
}
