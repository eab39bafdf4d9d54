// SPDX-License-Identifier: BSD-2-Clause
// The C API against the C++ API, in one process: its defaults are the C++ defaults, its
// codes and names the C++ ones, and on a PETS frame in every pixel format its detections
// and statistics are the C++ detector's, bit for bit.
#include <calped/calibration.h>
#include <calped/calped_c.h>
#include <calped/detector.h>
#include <calped/model.h>

#include "pixel_formats.h"
#include "test_data.h"

#include <cmath>
#include <cstdio>
#include <sys/stat.h>
#include <unistd.h>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace calped {
namespace {

TEST(CApi, DefaultsAreTheCppDefaults)
{
	calped_config c;
	std::memset(&c, 0xA5, sizeof(c));
	calped_config_defaults(&c);
	const DetectorConfig d;
	const CalibratedSettings s;
	const StaticRejection r;
	EXPECT_EQ(c.struct_size, sizeof(calped_config));
	EXPECT_EQ(c.max_width, d.maxWidth);
	EXPECT_EQ(c.max_height, d.maxHeight);
	EXPECT_EQ(c.resize, d.resize);
	EXPECT_EQ(int(c.resize_at), int(d.resizeAt));
	EXPECT_EQ(c.max_candidates, d.maxCandidates);
	EXPECT_TRUE(std::isnan(c.cascade_threshold) && std::isnan(d.cascadeThreshold));
	EXPECT_EQ(c.nms != 0, d.nms);
	EXPECT_EQ(int(c.method), int(d.method));
	EXPECT_EQ(c.min_person_height, s.minPersonHeight);
	EXPECT_EQ(c.max_person_height, s.maxPersonHeight);
	EXPECT_EQ(c.sparse_dense != 0, s.sparseDense);
	EXPECT_EQ(c.dense_region_persistence, s.denseRegionPersistence);
	EXPECT_EQ(c.max_dense_regions, s.maxDenseRegions);
	EXPECT_EQ(c.score_ratio != 0, s.scoreRatio);
	EXPECT_EQ(c.box_voting != 0, s.boxVoting);
	EXPECT_EQ(int(c.levels), int(s.levels));
	EXPECT_EQ(c.placed_level_reach, s.placedLevelReach);
	EXPECT_EQ(c.static_rejection != 0, d.staticRejection.has_value());
	EXPECT_EQ(c.static_difference, r.difference);
	EXPECT_EQ(c.static_min_foreground, r.minForeground);
	EXPECT_EQ(c.static_warmup_frames, r.warmupFrames);
	EXPECT_EQ(c.threads, d.threads);
	calped_error err;
	EXPECT_EQ(calped_config_validate(&c, nullptr, &err), CALPED_OK) << err.message;
}

TEST(CApi, StatusCodesAreTheErrorCodes)
{
	for (int code = 0; code <= int(ErrorCode::EndOfStream); code++)
		EXPECT_STREQ(calped_status_name(code), errorCodeName(ErrorCode(code)));
}

TEST(CApi, ConfigErrorsAreTheCppMessages)
{
	calped_config c;
	calped_config_defaults(&c);
	c.resize = 0.5; // below 1 inside the pyramid
	calped_error err;
	ASSERT_EQ(calped_config_validate(&c, nullptr, &err), CALPED_ERR_INVALID_ARGUMENT);
	DetectorConfig d;
	d.resize = 0.5;
	EXPECT_STREQ(err.message, d.validate().message());
}

// The C API's detections and statistics on `view` equal the C++ API's.
void expectSameAsCpp(const Model &model, const calped_model *cmodel, const CameraModel &camera,
		     const calped_camera *ccamera, const ImageView &view, const char *what)
{
	DetectorConfig d;
	d.maxWidth = view.width;
	d.maxHeight = view.height;
	d.resize = 2.0;
	d.camera = &camera;
	std::unique_ptr<Detector> cpp;
	ASSERT_TRUE(Detector::create(model, d, cpp).ok());
	Detections want;
	const Status st = cpp->detect(view, want);
	ASSERT_TRUE(st.ok()) << st.message();

	calped_config c;
	calped_config_defaults(&c);
	c.max_width = view.width;
	c.max_height = view.height;
	c.resize = 2.0;
	calped_error err;
	calped_detector *det = nullptr;
	ASSERT_EQ(calped_detector_create(cmodel, ccamera, &c, &det, &err), CALPED_OK) << err.message;
	calped_image im;
	std::memset(&im, 0, sizeof(im));
	for (int p = 0; p < 3; p++) {
		im.planes[p] = view.planes[p];
		im.strides[p] = view.strides[p];
	}
	im.width = view.width;
	im.height = view.height;
	im.format = int(view.format);
	im.yuv = int(view.yuv);
	const calped_detection *got = nullptr;
	int count = 0;
	ASSERT_EQ(calped_detect(det, &im, &got, &count, &err), CALPED_OK) << what << ": " << err.message;
	EXPECT_GT(count, 0) << what;
	ASSERT_EQ(count, want.count) << what;
	for (int i = 0; i < count; i++) {
		const Detection &w = want.items[i];
		const float g[8] = { got[i].x, got[i].y, got[i].w, got[i].h, got[i].score,
				     got[i].ground_x, got[i].ground_y, got[i].world_height };
		const float e[8] = { w.x, w.y, w.w, w.h, w.score, w.groundX, w.groundY, w.worldHeight };
		EXPECT_EQ(std::memcmp(g, e, sizeof(g)), 0) << what << ": detection " << i;
	}
	calped_stats stats;
	ASSERT_EQ(calped_detector_stats(det, &stats, &err), CALPED_OK);
	EXPECT_EQ(stats.windows, cpp->lastStats().windows) << what;
	EXPECT_EQ(stats.levels, cpp->lastStats().levels) << what;
	EXPECT_EQ(stats.computed_levels, cpp->lastStats().computedLevels) << what;
	EXPECT_EQ(int(calped_detector_method(det)), int(DetectionMethod::Calibrated));
	calped_detector_free(det);
}

// The *_load_file functions read like the programs: regular files only, capped by kind
// (docs/errors.md), so a FIFO cannot block and /dev/zero cannot exhaust memory.
TEST(CApi, FileReadsAreCappedRegularFilesLikeThePrograms)
{
	const std::string dir = ::testing::TempDir() + "capi-files-" + std::to_string(::getpid());
	ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
	const std::string fifo = dir + "/model.cpm";
	ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
	// A calibration one byte over the 4 MiB cap (sparse: nothing is written).
	const std::string big = dir + "/big.xml";
	std::FILE *f = std::fopen(big.c_str(), "w");
	ASSERT_NE(f, nullptr);
	ASSERT_EQ(::ftruncate(::fileno(f), (off_t(4) << 20) + 1), 0);
	std::fclose(f);

	calped_error err;
	calped_model *model = nullptr;
	EXPECT_EQ(calped_model_load_file(fifo.c_str(), &model, &err), CALPED_ERR_IO);
	EXPECT_NE(std::strstr(err.message, "is a FIFO, not a regular file"), nullptr) << err.message;
	EXPECT_EQ(calped_model_load_file("/dev/zero", &model, &err), CALPED_ERR_IO);
	EXPECT_NE(std::strstr(err.message, "/dev/zero: is a device or socket"), nullptr) << err.message;
	EXPECT_EQ(calped_model_load_file(dir.c_str(), &model, &err), CALPED_ERR_IO);
	EXPECT_NE(std::strstr(err.message, "is a directory"), nullptr) << err.message;
	EXPECT_EQ(model, nullptr);
	calped_camera *camera = nullptr;
	EXPECT_EQ(calped_camera_load_file(big.c_str(), &camera, &err), CALPED_ERR_IO);
	EXPECT_NE(std::strstr(err.message, "calibration "), nullptr) << err.message;
	EXPECT_NE(std::strstr(err.message, "4194305 bytes, over the 4194304-byte limit"), nullptr) << err.message;
	EXPECT_EQ(camera, nullptr);

	std::remove(fifo.c_str());
	std::remove(big.c_str());
	::rmdir(dir.c_str());
}

TEST(CApi, PetsFrameInEveryFormatIsTheCppDetection)
{
	const std::string blob = test::inriaModelBlob(), frame = test::petsFrame(1),
			  shared = test::sharedDir();
	if (blob.empty() || frame.empty() || shared.empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and PETS frame 1 (scripts/fetch-pets.sh 50)";
	const std::string calib = shared + "/data/pets2009-s2l1/View_001.xml";
	std::vector<uint8_t> bytes, text;
	Model model;
	CameraModel camera;
	test::RgbImage rgb;
	ASSERT_TRUE(test::readFile(blob, bytes) && test::readFile(calib, text) && test::loadRgb(frame, rgb));
	ASSERT_TRUE(loadModel(bytes.data(), bytes.size(), model).ok());
	ASSERT_TRUE(loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(), calib.c_str(), camera).ok());

	calped_error err;
	calped_model *cmodel = nullptr;
	calped_camera *ccamera = nullptr;
	ASSERT_EQ(calped_model_load_memory(bytes.data(), bytes.size(), &cmodel, &err), CALPED_OK) << err.message;
	ASSERT_EQ(calped_camera_load_file(calib.c_str(), &ccamera, &err), CALPED_OK) << err.message;
	EXPECT_EQ(std::string(calped_model_name(cmodel)), model.name);
	int w = 0, h = 0;
	calped_camera_image_size(ccamera, &w, &h);
	EXPECT_EQ(w, camera.imageWidth());
	EXPECT_EQ(h, camera.imageHeight());

	const PixelFormat formats[] = { PixelFormat::RGB8,       PixelFormat::BGR8,       PixelFormat::Gray8,
					PixelFormat::NV12,       PixelFormat::YUV420,     PixelFormat::YUYV,
					PixelFormat::BayerRGGB8, PixelFormat::BayerGRBG8, PixelFormat::BayerGBRG8,
					PixelFormat::BayerBGGR8 };
	for (PixelFormat f : formats) {
		const test::FormattedImage im = test::encodeImage(rgb.pixels.data(), rgb.width, rgb.height, f,
								  YuvEncoding::Bt601Limited, 3);
		expectSameAsCpp(model, cmodel, camera, ccamera, im.view(), pixelFormatName(f));
	}
	calped_model_free(cmodel);
	calped_camera_free(ccamera);
}

} // namespace
} // namespace calped
