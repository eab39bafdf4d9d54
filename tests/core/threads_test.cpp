// SPDX-License-Identifier: BSD-2-Clause
// DetectorConfig::threads: the detections (boxes, scores, world coordinates) and the
// counters are byte-identical for 1, 2, 3 and 4 threads, with either method, on synthetic
// frames in several pixel formats and on PETS frames (skipped without them). Its own
// binary: the ThreadSanitizer step of scripts/run-tests.sh builds and runs only this.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "core/thread_pool.h"
#include "pixel_formats.h"
#include "synthetic.h"
#include "test_data.h"

using namespace calped;

namespace {

// Every frame's detections and counters, as bytes, for one thread count.
std::string runFrames(const Model &model, DetectorConfig cfg, int threads,
		      const std::vector<test::FormattedImage> &frames)
{
	cfg.threads = threads;
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(model, cfg, det);
	EXPECT_TRUE(st.ok()) << st.message();
	if (!st.ok())
		return {};
	std::string out;
	for (const auto &f : frames) {
		Detections d;
		const Status s = det->detect(f.view(), d);
		EXPECT_TRUE(s.ok()) << s.message();
		out.append(reinterpret_cast<const char *>(d.items), sizeof(Detection) * size_t(d.count));
		const FrameStats &fs = det->lastStats();
		const uint64_t counters[] = { uint64_t(d.count),   uint64_t(fs.levels),  uint64_t(fs.computedLevels),
					      fs.windows,          fs.candidates,        fs.droppedWindows,
					      fs.sparseWindows,    fs.denseWindows,      uint64_t(fs.denseRegions),
					      fs.droppedRegions,   uint64_t(fs.staticRejected), fs.staticSkipped };
		out.append(reinterpret_cast<const char *>(counters), sizeof(counters));
	}
	return out;
}

// 2, 3 and 4 threads give what 1 gives; returns the detections of one thread.
size_t expectSameForAnyThreads(const Model &model, const DetectorConfig &cfg,
			       const std::vector<test::FormattedImage> &frames, const char *what)
{
	const std::string one = runFrames(model, cfg, 1, frames);
	EXPECT_FALSE(one.empty()) << what;
	for (int threads = 2; threads <= 4; threads++)
		EXPECT_TRUE(runFrames(model, cfg, threads, frames) == one) << what << ", " << threads << " threads";
	return one.size();
}

std::vector<test::FormattedImage> syntheticFrames(int w, int h, PixelFormat f, int count = 3)
{
	std::vector<test::FormattedImage> frames;
	for (uint32_t s = 0; s < uint32_t(count); s++) {
		const std::vector<uint8_t> rgb = test::randomImage(s, w, h);
		frames.push_back(test::encodeImage(rgb.data(), w, h, f));
	}
	return frames;
}

} // namespace

TEST(ThreadPool, RunsEveryTaskOnceOnAnyThreadCount)
{
	for (int threads : { 1, 2, 3, 4, 7 }) {
		ThreadPool pool;
		ASSERT_TRUE(pool.start(threads).ok());
		EXPECT_EQ(pool.size(), threads);
		for (int count : { 0, 1, 2, 5, 100 }) {
			std::vector<int> hits(size_t(count), 0);
			std::vector<int> worker(size_t(count), -1);
			auto task = [&](int t, int w) {
				hits[size_t(t)]++;
				worker[size_t(t)] = w;
			};
			for (int round = 0; round < 20; round++)
				pool.forEach(count, task);
			for (int t = 0; t < count; t++) {
				EXPECT_EQ(hits[size_t(t)], 20) << threads << " threads, task " << t;
				EXPECT_GE(worker[size_t(t)], 0);
				EXPECT_LT(worker[size_t(t)], threads);
			}
		}
	}
}

TEST(ThreadPool, RefusesThreadCountsOutOfRange)
{
	ThreadPool pool;
	for (int bad : { 0, -1, 65 }) {
		const Status st = pool.start(bad);
		EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
		EXPECT_NE(std::strstr(st.message(), "threads"), nullptr) << st.message();
	}
	DetectorConfig cfg;
	cfg.threads = 65;
	const Status st = cfg.validate();
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::strstr(st.message(), "threads 65 is outside 1..64"), nullptr) << st.message();
}

// Every parallel section once, small: what the ThreadSanitizer step runs (the cases below
// take minutes under it). Generic: a smaller NV12 frame than the maximum (strips converted
// per thread, taps built per thread); calibrated: placed levels (rectangles) with the
// static gate, and the toolbox's octaves (bands); 1 and 3 threads.
TEST(Threads, EverySectionOnce)
{
	const Model model = test::randomModel(7, 256);
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.resize = 2.0;
	cfg.cascadeThreshold = -10.0f;
	const std::vector<uint8_t> rgb = test::randomImage(1, 201, 153);
	const std::vector<test::FormattedImage> small = { test::encodeImage(rgb.data(), 201, 153, PixelFormat::NV12) };
	auto same = [&](const DetectorConfig &c, const std::vector<test::FormattedImage> &frames, const char *what) {
		const std::string one = runFrames(model, c, 1, frames);
		EXPECT_FALSE(one.empty()) << what;
		EXPECT_TRUE(runFrames(model, c, 3, frames) == one) << what;
	};
	same(cfg, small, "generic");
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	cfg.camera = &camera;
	cfg.method = DetectionMethod::Calibrated;
	cfg.staticRejection = StaticRejection();
	cfg.staticRejection->warmupFrames = 1;
	same(cfg, syntheticFrames(320, 240, PixelFormat::RGB8, 2), "calibrated, placed, static gate");
	cfg.staticRejection.reset();
	cfg.calibrated = CalibratedSettings();
	cfg.calibrated->levels = PyramidLevels::Toolbox;
	same(cfg, syntheticFrames(320, 240, PixelFormat::RGB8, 1), "calibrated, toolbox");
}

TEST(Threads, SyntheticGenericSameForAnyThreadCount)
{
	const Model model = test::randomModel(7, 512);
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.cascadeThreshold = -10.0f; // many candidates: NMS and the gathering order matter
	// Resize 1; resize 2 in the pyramid from NV12 (strips converted per thread); resize 2
	// of the frame first.
	const struct {
		double resize;
		ResizeAt at;
		PixelFormat format;
	} cases[] = { { 1.0, ResizeAt::Pyramid, PixelFormat::RGB8 },
		      { 2.0, ResizeAt::Pyramid, PixelFormat::NV12 },
		      { 2.0, ResizeAt::Frame, PixelFormat::RGB8 } };
	for (const auto &c : cases) {
		cfg.resize = c.resize;
		cfg.resizeAt = c.at;
		const std::string what = std::string("generic, ") + pixelFormatName(c.format) +
					 (c.at == ResizeAt::Pyramid ? ", pyramid" : ", frame") + " resize " +
					 std::to_string(c.resize);
		expectSameForAnyThreads(model, cfg, syntheticFrames(320, 240, c.format, 2), what.c_str());
	}
	// Smaller frames than the maximum (taps built per frame, per thread) and few
	// candidates kept (the first ones of the levels in order, the rest dropped).
	cfg.resize = 2.0;
	cfg.resizeAt = ResizeAt::Pyramid;
	cfg.maxCandidates = 50;
	std::vector<test::FormattedImage> small = syntheticFrames(201, 153, PixelFormat::RGB8, 2);
	expectSameForAnyThreads(model, cfg, small, "generic, smaller frames, 50 candidates");
}

TEST(Threads, SyntheticCalibratedSameForAnyThreadCount)
{
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	const Model model = test::randomModel(7, 512);
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.resize = 2.0;
	cfg.camera = &camera;
	cfg.method = DetectionMethod::Calibrated;
	cfg.cascadeThreshold = -10.0f;
	// Placed levels (rectangles), the toolbox's octaves (bands), every plausible window,
	// the frame resized first, and the static gate.
	for (int variant = 0; variant < 5; variant++) {
		cfg.resizeAt = variant == 3 ? ResizeAt::Frame : ResizeAt::Pyramid;
		cfg.calibrated = CalibratedSettings();
		cfg.calibrated->levels = variant == 0 || variant == 4 ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cfg.calibrated->sparseDense = variant != 2;
		cfg.staticRejection.reset();
		if (variant == 4) {
			cfg.staticRejection = StaticRejection();
			cfg.staticRejection->warmupFrames = 1;
		}
		const std::string what = "calibrated variant " + std::to_string(variant);
		expectSameForAnyThreads(model, cfg, syntheticFrames(320, 240, variant == 1 ? PixelFormat::YUYV : PixelFormat::RGB8),
					what.c_str());
	}
}

TEST(Threads, PetsSameForAnyThreadCount)
{
	const std::string shared = test::sharedDir();
	const std::string blobPath = test::inriaModelBlob();
	if (shared.empty() || blobPath.empty() || test::petsFrame(402).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	std::vector<uint8_t> blob, xml;
	ASSERT_TRUE(test::readFile(blobPath, blob));
	ASSERT_TRUE(test::readFile(shared + "/data/pets2009-s2l1/View_001.xml", xml));
	Model model;
	ASSERT_TRUE(loadModel(blob.data(), blob.size(), model).ok());
	CameraModel camera;
	ASSERT_TRUE(loadCalibration(reinterpret_cast<const char *>(xml.data()), xml.size(), "View_001.xml", camera).ok());
	std::vector<test::FormattedImage> frames;
	for (int k : { 400, 401, 402 }) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		frames.push_back(test::encodeImage(img.pixels.data(), img.width, img.height, PixelFormat::RGB8));
	}
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = 2.0;
	cfg.camera = &camera; // the default: the calibrated method, placed levels
	EXPECT_GT(expectSameForAnyThreads(model, cfg, frames, "PETS calibrated"), 3 * 12 * sizeof(uint64_t));
	cfg.method = DetectionMethod::Generic;
	cfg.resize = 1.0;
	EXPECT_GT(expectSameForAnyThreads(model, cfg, frames, "PETS generic"), 3 * 12 * sizeof(uint64_t));
}

// LDCF: each thread filters the levels it prepares into its own buffer. Generic, and
// calibrated with placed levels (rectangles), the toolbox's octaves (bands) and every
// plausible window.
TEST(Threads, SyntheticLdcfSameForAnyThreadCount)
{
	const Model model = test::randomLdcfModel(7, 256);
	DetectorConfig cfg;
	cfg.maxWidth = 320;
	cfg.maxHeight = 240;
	cfg.cascadeThreshold = -10.0f;
	expectSameForAnyThreads(model, cfg, syntheticFrames(320, 240, PixelFormat::RGB8, 1), "LDCF generic");
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	cfg.resize = 2.0;
	cfg.camera = &camera;
	cfg.method = DetectionMethod::Calibrated;
	for (int variant = 0; variant < 3; variant++) {
		cfg.calibrated = CalibratedSettings();
		cfg.calibrated->levels = variant == 0 ? PyramidLevels::Placed : PyramidLevels::Toolbox;
		cfg.calibrated->sparseDense = variant != 2;
		const std::string what = "LDCF calibrated variant " + std::to_string(variant);
		expectSameForAnyThreads(model, cfg, syntheticFrames(320, 240, PixelFormat::RGB8, 1), what.c_str());
	}
}
