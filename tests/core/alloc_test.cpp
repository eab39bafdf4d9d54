// SPDX-License-Identifier: BSD-2-Clause
// Bounded memory: after Detector::create(), detect() allocates nothing on the heap.
// This binary links tests/common/alloc_counter.cpp, which replaces operator new to count calls.
#include <cmath>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <new>

#include <calped/calped.h>

#include "common/alloc_counter.h"
#include "detect/detector_internals.h"
#include "pixel_formats.h"
#include "synthetic.h"
#include "test_data.h"

using namespace calped;

namespace {

// Runs detect() on each image with counting on; returns the allocations seen.
long allocationsDuring(Detector &det, const std::vector<std::vector<uint8_t>> &images, int w, int h,
		       int *detections)
{
	test::startCountingAllocations();
	for (const auto &img : images) {
		Detections d;
		const Status st = det.detect(ImageView::rgb8(img.data(), w, h), d);
		if (st.ok())
			*detections += d.count;
	}
	return test::stopCountingAllocations();
}

// The same for frames already in their pixel format.
long allocationsDuring(Detector &det, const std::vector<test::FormattedImage> &images,
		       int *detections)
{
	test::startCountingAllocations();
	for (const auto &img : images) {
		Detections d;
		const Status st = det.detect(img.view(), d);
		if (st.ok())
			*detections += d.count;
	}
	return test::stopCountingAllocations();
}

const PixelFormat kAllFormats[] = { PixelFormat::RGB8,       PixelFormat::BGR8,
				    PixelFormat::Gray8,      PixelFormat::NV12,
				    PixelFormat::YUV420,     PixelFormat::YUYV,
				    PixelFormat::BayerRGGB8, PixelFormat::BayerGRBG8,
				    PixelFormat::BayerGBRG8, PixelFormat::BayerBGGR8 };

} // namespace

TEST(BoundedMemory, CountingAllocatorSeesAllocations)
{
	// The counter itself must work, or the tests below prove nothing.
	test::startCountingAllocations();
	std::vector<int> *v = new std::vector<int>(100);
	const long seen = test::stopCountingAllocations();
	delete v;
	EXPECT_GE(seen, 1); // GCC may merge or elide some of the two allocations
}

TEST(BoundedMemory, DetectAllocatesNothingSynthetic)
{
	const Model model = test::randomModel(7, 512);
	// Resizes of the frame (2.5: a ratio other than 2, a separate SIMD path), then
	// resizes inside the pyramid (negative here).
	for (double resize : { 1.0, 2.0, 2.5, -2.0, -2.5 }) {
		DetectorConfig cfg;
		cfg.maxWidth = 320;
		cfg.maxHeight = 240;
		cfg.resize = std::fabs(resize);
		cfg.resizeAt = resize < 0 ? ResizeAt::Pyramid : ResizeAt::Frame;
		cfg.cascadeThreshold = -10.0f; // let many windows through, to exercise NMS
		std::unique_ptr<Detector> det;
		ASSERT_TRUE(Detector::create(model, cfg, det).ok());
		std::vector<std::vector<uint8_t>> frames;
		for (uint32_t s = 0; s < 4; s++)
			frames.push_back(test::randomImage(s, 320, 240));
		// Smaller frames and a bad one go through the same path without allocating.
		int detections = 0;
		EXPECT_EQ(allocationsDuring(*det, frames, 320, 240, &detections), 0) << "resize " << resize;
		std::vector<std::vector<uint8_t>> small = { test::randomImage(9, 200, 150) };
		EXPECT_EQ(allocationsDuring(*det, small, 200, 150, &detections), 0) << "resize " << resize;
		std::vector<std::vector<uint8_t>> tooBig = { test::randomImage(9, 400, 300) };
		EXPECT_EQ(allocationsDuring(*det, tooBig, 400, 300, &detections), 0) << "resize " << resize;
		std::printf("resize %.1f%s: %d detections over the frames, 0 allocations\n", cfg.resize,
			    cfg.resizeAt == ResizeAt::Pyramid ? " in the pyramid" : "", detections);
		EXPECT_GT(detections, 0);
	}
}

// --calib auto's collecting phase: the generic method plus the observation buffer. A random
// model's confident boxes are no people to calibrate from: every frame collects, none
// estimates (estimates may allocate; collecting frames may not).
TEST(BoundedMemory, SelfCalibratingCollectingFramesAllocateNothing)
{
	const Model model = test::randomModel(7, 512);
	SelfCalibratingConfig cfg;
	cfg.detector.maxWidth = 320;
	cfg.detector.maxHeight = 240;
	cfg.detector.resize = 1.0;
	cfg.estimateEvery = 1000;
	std::unique_ptr<SelfCalibratingDetector> det;
	ASSERT_TRUE(SelfCalibratingDetector::create(model, cfg, det).ok());
	std::vector<std::vector<uint8_t>> frames;
	for (uint32_t s = 0; s < 4; s++)
		frames.push_back(test::randomImage(s, 320, 240));
	Detections out;
	ASSERT_TRUE(det->detect(ImageView::rgb8(frames[0].data(), 320, 240), out).ok()); // warm
	test::startCountingAllocations();
	for (int k = 0; k < 20; k++)
		EXPECT_TRUE(det->detect(ImageView::rgb8(frames[size_t(k) % 4].data(), 320, 240), out).ok());
	const long allocations = test::stopCountingAllocations();
	EXPECT_EQ(allocations, 0);
	EXPECT_EQ(det->lastMethod(), DetectionMethod::Generic);
	EXPECT_EQ(det->cameraEstimate(), 0);
	// A camera in the configuration, another method, or settings out of range: refused.
	CameraModel camera;
	ASSERT_TRUE(makeSelfCalibratedCamera(800, 0.3, 0, 5, 160, 120, camera).ok());
	SelfCalibratingConfig bad = cfg;
	bad.detector.camera = &camera;
	EXPECT_EQ(SelfCalibratingDetector::create(model, bad, det).code(), ErrorCode::InvalidArgument);
	bad = cfg;
	bad.detector.method = DetectionMethod::Generic;
	EXPECT_EQ(SelfCalibratingDetector::create(model, bad, det).code(), ErrorCode::InvalidArgument);
	bad = cfg;
	bad.checkEvery = 0;
	EXPECT_EQ(SelfCalibratingDetector::create(model, bad, det).code(), ErrorCode::InvalidArgument);
	bad = cfg;
	bad.minCheckFit = 1.5;
	EXPECT_EQ(SelfCalibratingDetector::create(model, bad, det).code(), ErrorCode::InvalidArgument);
}

TEST(BoundedMemory, StaticRejectionAllocatesNothingAndDropsAStaticScene)
{
	// One random frame over and over: once the background is trusted, everything the
	// detector finds on it is static, in any pixel format.
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.cascadeThreshold = -10.0f;
	cfg.staticRejection = StaticRejection();
	cfg.staticRejection->warmupFrames = 2;
	std::unique_ptr<Detector> det;
	ASSERT_TRUE(Detector::create(test::randomModel(7, 512), cfg, det).ok());
	const std::vector<uint8_t> rgb = test::randomImage(3, 320, 240);
	for (PixelFormat f : { PixelFormat::RGB8, PixelFormat::NV12 }) {
		const std::vector<test::FormattedImage> frames(4, test::encodeImage(rgb.data(), 320, 240, f));
		int detections = 0;
		EXPECT_EQ(allocationsDuring(*det, frames, &detections), 0) << pixelFormatName(f);
		EXPECT_GT(det->lastStats().staticRejected, 0) << pixelFormatName(f);
		Detections last;
		ASSERT_TRUE(det->detect(frames[0].view(), last).ok());
		EXPECT_EQ(last.count, 0) << pixelFormatName(f);
		std::printf("static rejection, %s: %d detections over 4 frames, %d dropped in the last, "
			    "0 allocations\n",
			    pixelFormatName(f), detections, det->lastStats().staticRejected);
	}
}

TEST(BoundedMemory, CalibratedDetectAllocatesNothing)
{
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.resize = 2.0;
	cfg.method = DetectionMethod::Calibrated;
	cfg.camera = &camera;
	cfg.cascadeThreshold = -10.0f;
	// The resized frame, the resize inside the pyramid, levels placed among the needed
	// ones (PyramidLevels::Placed, which needs the resize in the pyramid), and these with
	// the static scene's gate of the sparse grid.
	for (int variant = 0; variant < 4; variant++) {
		cfg.resizeAt = variant > 0 ? ResizeAt::Pyramid : ResizeAt::Frame;
		cfg.calibrated = CalibratedSettings();
		cfg.calibrated->levels = variant >= 2 ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cfg.staticRejection.reset();
		if (variant == 3) {
			cfg.staticRejection = StaticRejection();
			cfg.staticRejection->warmupFrames = 1;
		}
		std::unique_ptr<Detector> det;
		ASSERT_TRUE(Detector::create(test::randomModel(7, 512), cfg, det).ok());
		std::vector<std::vector<uint8_t>> frames;
		for (uint32_t s = 0; s < 3; s++)
			frames.push_back(test::randomImage(s, 320, 240));
		int detections = 0;
		EXPECT_EQ(allocationsDuring(*det, frames, 320, 240, &detections), 0);
		std::printf("calibrated, resize 2%s%s%s: %d detections, %llu windows in the last frame, "
			    "0 allocations\n",
			    cfg.resizeAt == ResizeAt::Pyramid ? " in the pyramid" : "",
			    variant >= 2 ? ", placed levels" : "",
			    cfg.staticRejection ? ", static gate" : "", detections,
			    (unsigned long long)det->lastStats().windows);
		EXPECT_GT(det->lastStats().windows, 0u);
		// Placed levels are computed in rectangles around what each pass reads
		// (Pyramid::compute with rectangles): that path ran in these frames.
		if (variant >= 2) {
			EXPECT_GT(DetectorInternals::of(*det).pyramid.rectsComputed, 0);
		}
	}
}

TEST(BoundedMemory, FourThreadsAllocateNothing)
{
	// The pool's hand-off, the per-thread scratch and the candidate lanes: made by
	// create(), nothing per frame, with either method and a converted pixel format.
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	const Model model = test::randomModel(7, 512);
	for (int variant = 0; variant < 3; variant++) {
		DetectorConfig cfg;
		cfg.maxWidth = 320;
		cfg.maxHeight = 240;
		cfg.resize = 2.0;
		cfg.cascadeThreshold = -10.0f;
		cfg.threads = 4;
		if (variant > 0) {
			cfg.camera = &camera;
			cfg.method = DetectionMethod::Calibrated;
			cfg.calibrated = CalibratedSettings();
			cfg.calibrated->levels = variant == 1 ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		}
		std::unique_ptr<Detector> det;
		ASSERT_TRUE(Detector::create(model, cfg, det).ok());
		std::vector<test::FormattedImage> frames;
		for (uint32_t s = 0; s < 3; s++) {
			const auto rgb = test::randomImage(s, 320, 240);
			frames.push_back(test::encodeImage(rgb.data(), 320, 240, s == 1 ? PixelFormat::NV12 : PixelFormat::RGB8));
		}
		// Smaller frames take another path (taps built per frame) without a camera.
		if (variant == 0) {
			const auto rgb = test::randomImage(9, 201, 153);
			frames.push_back(test::encodeImage(rgb.data(), 201, 153, PixelFormat::RGB8));
		}
		int detections = 0;
		EXPECT_EQ(allocationsDuring(*det, frames, &detections), 0) << "variant " << variant;
		EXPECT_GT(det->lastStats().windows, 0u);
		std::printf("4 threads, %s: %d detections, 0 allocations\n",
			    variant == 0 ? "generic" : variant == 1 ? "calibrated, placed levels" : "calibrated, toolbox levels",
			    detections);
	}
}

TEST(BoundedMemory, DetectAllocatesNothingOnPets)
{
	const std::string blobPath = test::inriaModelBlob();
	if (blobPath.empty() || test::petsFrame(3).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	std::vector<uint8_t> blob;
	ASSERT_TRUE(test::readFile(blobPath, blob));
	Model model;
	ASSERT_TRUE(loadModel(blob.data(), blob.size(), model).ok());
	std::vector<std::vector<uint8_t>> frames;
	for (int k = 1; k <= 3; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		frames.push_back(img.pixels);
	}
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = 2.0;
	std::unique_ptr<Detector> det;
	ASSERT_TRUE(Detector::create(model, cfg, det).ok());
	int detections = 0;
	EXPECT_EQ(allocationsDuring(*det, frames, 768, 576, &detections), 0);
	std::printf("PETS frames 1-3 at resize 2: %d detections, 0 allocations\n", detections);
	EXPECT_GT(detections, 0);
}

TEST(BoundedMemory, EveryPixelFormatAllocatesNothing)
{
	// Strip-wise conversion at resize 1, whole-frame conversion before resize 2; full,
	// smaller odd-sized and rejected frames of every format.
	const Model model = test::randomModel(7, 512);
	// Resizes of the frame, then resizes inside the pyramid (negative here).
	for (double resize : { 1.0, 2.0, -2.0, -2.5 }) {
		DetectorConfig cfg;
		cfg.maxWidth = 320;
		cfg.maxHeight = 240;
		cfg.resize = std::fabs(resize);
		cfg.resizeAt = resize < 0 ? ResizeAt::Pyramid : ResizeAt::Frame;
		cfg.cascadeThreshold = -10.0f;
		std::unique_ptr<Detector> det;
		ASSERT_TRUE(Detector::create(model, cfg, det).ok());
		const auto full = test::randomImage(1, 320, 240), small = test::randomImage(2, 201, 153),
			   big = test::randomImage(3, 330, 240);
		for (PixelFormat f : kAllFormats) {
			std::vector<test::FormattedImage> frames = {
				test::encodeImage(full.data(), 320, 240, f, YuvEncoding::Bt709Full, 4),
				test::encodeImage(small.data(), 201, 153, f),
				test::encodeImage(big.data(), 330, 240, f),
			};
			int detections = 0;
			EXPECT_EQ(allocationsDuring(*det, frames, &detections), 0)
				<< pixelFormatName(f) << " resize " << resize;
			EXPECT_GT(detections, 0) << pixelFormatName(f) << " resize " << resize;
		}
	}
}

TEST(BoundedMemory, PetsInEveryPixelFormatAllocatesNothing)
{
	const std::string blobPath = test::inriaModelBlob();
	if (blobPath.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	std::vector<uint8_t> blob;
	ASSERT_TRUE(test::readFile(blobPath, blob));
	Model model;
	ASSERT_TRUE(loadModel(blob.data(), blob.size(), model).ok());
	test::RgbImage img;
	ASSERT_TRUE(test::loadRgb(test::petsFrame(1), img));
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	std::unique_ptr<Detector> det;
	ASSERT_TRUE(Detector::create(model, cfg, det).ok());
	for (PixelFormat f : kAllFormats) {
		std::vector<test::FormattedImage> frames = {
			test::encodeImage(img.pixels.data(), img.width, img.height, f) };
		int detections = 0;
		EXPECT_EQ(allocationsDuring(*det, frames, &detections), 0) << pixelFormatName(f);
		std::printf("PETS frame 1 as %s at resize 1: %d detections, 0 allocations\n",
			    pixelFormatName(f), detections);
		EXPECT_GT(detections, 0) << pixelFormatName(f);
	}
}

namespace {

// One detector of `model` on three 320x240 synthetic frames, generic or calibrated (the
// synthetic camera, resize 2 in the pyramid, placed levels), on `threads`: no allocation
// in detect(), windows classified and, calibrated, rectangles computed. Returns the
// detections.
int expectAllocationFree(const Model &model, bool calibrated, int threads, const char *what)
{
	CameraModel camera;
	EXPECT_TRUE(test::syntheticCamera(camera));
	std::vector<std::vector<uint8_t>> frames;
	for (uint32_t s = 0; s < 3; s++)
		frames.push_back(test::randomImage(s, 320, 240));
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.cascadeThreshold = -10.0f;
	cfg.threads = threads;
	if (calibrated) {
		cfg.method = DetectionMethod::Calibrated;
		cfg.camera = &camera;
		cfg.resize = 2.0;
		cfg.resizeAt = ResizeAt::Pyramid;
		cfg.calibrated = CalibratedSettings();
		cfg.calibrated->levels = PyramidLevels::Placed;
	}
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(model, cfg, det);
	EXPECT_TRUE(st.ok()) << what << ": " << st.message();
	if (!st.ok())
		return 0;
	int detections = 0;
	EXPECT_EQ(allocationsDuring(*det, frames, 320, 240, &detections), 0) << what;
	std::printf("%s: %d detections, %llu windows in the last frame, 0 allocations\n", what, detections,
		    (unsigned long long)det->lastStats().windows);
	EXPECT_GT(det->lastStats().windows, 0u) << what;
	if (calibrated) {
		EXPECT_GT(DetectorInternals::of(*det).pyramid.rectsComputed, 0) << what;
	}
	return detections;
}

} // namespace

// The Caltech+ model's options (shrink 2, softBin 1, no colour smoothing, 64x32 windows;
// the same 5120 features as INRIA): 2x2 cells and spatially interpolated histograms, in
// the generic method and the calibrated one with placed levels in rectangles.
TEST(BoundedMemory, ShrinkTwoModelAllocatesNothing)
{
	Model model = test::randomModel(11, 512);
	ModelParams &p = model.params;
	p.shrink = 2;
	p.histBinSize = 2;
	p.softBin = 1;
	p.colorSmooth = 0;
	p.modelDsH = 50;
	p.modelDsW = 20.5f;
	p.modelDsPadH = 64;
	p.modelDsPadW = 32;
	p.minDsH = 50;
	p.minDsW = 20.5f;
	p.padH = 8;
	p.padW = 6;
	ASSERT_TRUE(validateModel(model).ok()) << validateModel(model).message();
	ASSERT_EQ(model.featureCount(), 5120);
	expectAllocationFree(model, false, 1, "shrink 2, generic");
	expectAllocationFree(model, true, 1, "shrink 2, calibrated, placed levels");
}

// LDCF (LdcfInriaDetector's options: shrink 2, four 5x5 filters per channel): the filter
// stage's buffers are made by create(), in the generic method, the calibrated one with
// placed levels in rectangles, and on threads.
TEST(BoundedMemory, LdcfModelAllocatesNothing)
{
	const Model model = test::randomLdcfModel(12, 256);
	ASSERT_TRUE(validateModel(model).ok()) << validateModel(model).message();
	ASSERT_EQ(model.featureCount(), 40 * 32 * 16);
	EXPECT_GT(expectAllocationFree(model, false, 1, "LDCF, generic"), 0);
	EXPECT_GT(expectAllocationFree(model, true, 1, "LDCF, calibrated, placed levels"), 0);
	EXPECT_GT(expectAllocationFree(model, true, 2, "LDCF, calibrated, 2 threads"), 0);
}
