// SPDX-License-Identifier: BSD-2-Clause
// DetectorConfig: the defaults are the best configuration, and every setting that is out
// of range or that the rest of the configuration would ignore is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <unistd.h>

#include <calped/calped.h>

#include "detect/memory_estimate.h"
#include "pyramid/ldcf_filter.h"
#include "synthetic.h"

namespace calped {
namespace {

// A 640x480 camera 2 m above the ground, looking level.
CameraModel testCamera()
{
	Eigen::Matrix3d K;
	K << 600, 0, 320, 0, 600, 120, 0, 0, 1;
	Eigen::Matrix3d R;
	R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	CameraModel camera;
	EXPECT_TRUE(CameraModel::fromPinhole(K, R, Eigen::Vector3d(0, 2.0, 0), LengthUnit::Metre, camera).ok());
	return camera;
}

DetectorConfig base(const CameraModel *camera)
{
	DetectorConfig c;
	c.maxWidth = 640;
	c.maxHeight = 480;
	c.camera = camera;
	return c;
}

TEST(DetectorConfig, DefaultsAreTheBestConfiguration)
{
	const CameraModel camera = testCamera();
	ASSERT_FALSE(::testing::Test::HasFailure());
	const Model model = test::randomModel(1);
	std::unique_ptr<Detector> det;
	// With a camera: the calibrated method, resize inside the pyramid, placed levels,
	// sparse and dense windows, box voting and the score ratio; no static rejection.
	ASSERT_TRUE(Detector::create(model, base(&camera), det).ok());
	const DetectorConfig &c = det->config();
	EXPECT_EQ(c.method, DetectionMethod::Calibrated);
	EXPECT_EQ(c.resizeAt, ResizeAt::Pyramid);
	ASSERT_TRUE(c.calibrated.has_value());
	EXPECT_EQ(c.calibrated->levels, PyramidLevels::Placed);
	EXPECT_TRUE(c.calibrated->sparseDense);
	EXPECT_TRUE(c.calibrated->boxVoting);
	EXPECT_FALSE(c.calibrated->scoreRatio);
	EXPECT_EQ(c.calibrated->denseRegionPersistence, 3);
	EXPECT_TRUE(c.nms);
	EXPECT_FALSE(c.staticRejection.has_value());
	EXPECT_EQ(c.camera != nullptr, true);
	// Without: the generic method and nothing calibrated.
	ASSERT_TRUE(Detector::create(model, base(nullptr), det).ok());
	EXPECT_EQ(det->config().method, DetectionMethod::Generic);
	EXPECT_FALSE(det->config().calibrated.has_value());
	// The method named explicitly wins over the camera.
	DetectorConfig generic = base(&camera);
	generic.method = DetectionMethod::Generic;
	ASSERT_TRUE(Detector::create(model, generic, det).ok());
	EXPECT_EQ(det->config().method, DetectionMethod::Generic);
}

struct Refusal {
	const char *what;     // the setting the message must name
	std::function<void(DetectorConfig &)> set;
	bool camera;          // start from a configuration with the camera (calibrated)
};

TEST(DetectorConfig, EveryMeaninglessOrOutOfRangeSettingIsRefusedByName)
{
	const CameraModel camera = testCamera();
	ASSERT_FALSE(::testing::Test::HasFailure());
	const Model model = test::randomModel(1);
	const std::vector<Refusal> refusals = {
		{ "maximum frame size", [](DetectorConfig &c) { c.maxWidth = 0; }, false },
		{ "maximum frame size", [](DetectorConfig &c) { c.maxHeight = 20000; }, false },
		{ "resize", [](DetectorConfig &c) { c.resize = 0; }, false },
		{ "resize", [](DetectorConfig &c) { c.resize = 9; }, false },
		{ "resizeAt Frame", [](DetectorConfig &c) { c.resize = 0.5; }, false },
		{ "leaves no pixels",
		  [](DetectorConfig &c) {
			  c.resize = 0.0001;
			  c.resizeAt = ResizeAt::Frame;
		  },
		  false },
		{ "maxCandidates", [](DetectorConfig &c) { c.maxCandidates = 0; }, false },
		{ "cascadeThreshold", [](DetectorConfig &c) { c.cascadeThreshold = 40000.0f; }, false },
		{ "cascadeThreshold", [](DetectorConfig &c) { c.cascadeThreshold = -INFINITY; }, false },
		{ "needs a camera", [](DetectorConfig &c) { c.method = DetectionMethod::Calibrated; }, false },
		{ "method is generic", [](DetectorConfig &c) { c.calibrated = CalibratedSettings(); }, false },
		{ "method is generic",
		  [](DetectorConfig &c) {
			  c.method = DetectionMethod::Generic;
			  c.calibrated = CalibratedSettings();
		  },
		  true },
		{ "minPersonHeight",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->minPersonHeight = 2.5;
		  },
		  true },
		{ "maxPersonHeight",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->maxPersonHeight = 12;
		  },
		  true },
		{ "denseRegionPersistence",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->denseRegionPersistence = 0;
		  },
		  true },
		{ "maxDenseRegions",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->maxDenseRegions = 0;
		  },
		  true },
		{ "placedLevelReach",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->placedLevelReach = 17;
		  },
		  true },
		{ "resizeAt Pyramid",
		  [](DetectorConfig &c) {
			  c.resize = 2;
			  c.resizeAt = ResizeAt::Frame; // placed levels by default
		  },
		  true },
		{ "boxVoting", [](DetectorConfig &c) { c.nms = false; }, true },
		{ "scoreRatio",
		  [](DetectorConfig &c) {
			  c.nms = false;
			  c.calibrated = CalibratedSettings();
			  c.calibrated->boxVoting = false;
			  c.calibrated->scoreRatio = true;
		  },
		  true },
		{ "sparseDense only",
		  [](DetectorConfig &c) {
			  c.calibrated = CalibratedSettings();
			  c.calibrated->sparseDense = false;
			  c.calibrated->denseRegionPersistence = 5;
		  },
		  true },
		{ "staticRejection.difference",
		  [](DetectorConfig &c) {
			  c.staticRejection = StaticRejection();
			  c.staticRejection->difference = 0;
		  },
		  false },
		{ "staticRejection.minForeground",
		  [](DetectorConfig &c) {
			  c.staticRejection = StaticRejection();
			  c.staticRejection->minForeground = 1.5f;
		  },
		  false },
		{ "staticRejection.warmupFrames",
		  [](DetectorConfig &c) {
			  c.staticRejection = StaticRejection();
			  c.staticRejection->warmupFrames = 0;
		  },
		  false },
	};
	for (const Refusal &r : refusals) {
		DetectorConfig c = base(r.camera ? &camera : nullptr);
		ASSERT_TRUE(c.validate().ok());
		r.set(c);
		const Status st = c.validate();
		EXPECT_EQ(st.code(), ErrorCode::InvalidArgument) << r.what;
		EXPECT_NE(std::string(st.message()).find(r.what), std::string::npos)
			<< "expected '" << r.what << "' in: " << st.message();
		// create() refuses it the same way, before allocating anything.
		std::unique_ptr<Detector> det;
		EXPECT_EQ(Detector::create(model, c, det).code(), ErrorCode::InvalidArgument) << r.what;
		EXPECT_EQ(det, nullptr);
	}
	// Each of the calibrated method's switches off, alone or together, is meaningful.
	DetectorConfig c = base(&camera);
	c.calibrated = CalibratedSettings();
	c.calibrated->sparseDense = false;
	c.calibrated->boxVoting = false;
	c.calibrated->scoreRatio = false;
	c.calibrated->levels = PyramidLevels::Toolbox;
	c.nms = false;
	c.resize = 2;
	c.resizeAt = ResizeAt::Frame;
	c.staticRejection = StaticRejection();
	EXPECT_TRUE(c.validate().ok()) << c.validate().message();
}

// The frame-sized buffers are estimated before any is allocated: a model asking for four
// octaves up (13.4 GB on a PETS frame before this check) and a huge frame at resize 2
// are refused with the need and the budget; the budget can be raised or lifted.
TEST(DetectorConfig, MemoryBeyondTheBudgetIsRefusedBeforeAllocating)
{
	Model model = test::randomModel(1);
	DetectorConfig c;
	c.maxWidth = 768;
	c.maxHeight = 576;
	std::unique_ptr<Detector> det;
	ASSERT_TRUE(Detector::create(model, c, det).ok());
	model.params.nOctUp = 4;
	Status st = Detector::create(model, c, det);
	EXPECT_EQ(st.code(), ErrorCode::OutOfMemory) << st.message();
	EXPECT_NE(std::string(st.message()).find("nOctUp 4 need about 4.2"), std::string::npos) << st.message();
	EXPECT_NE(std::string(st.message()).find("budget of 1.00 GiB"), std::string::npos) << st.message();
	EXPECT_EQ(det, nullptr);

	model = test::randomModel(1);
	c.maxWidth = c.maxHeight = 8192;
	c.resize = 2;
	st = Detector::create(model, c, det);
	EXPECT_EQ(st.code(), ErrorCode::OutOfMemory) << st.message();
	EXPECT_NE(std::string(st.message()).find("8192x8192 frames at resize 2"), std::string::npos) << st.message();

	// 1920x1080 at resize 2: about 0.35 GiB, refused under a 256 MiB budget, taken with none.
	c.maxWidth = 1920;
	c.maxHeight = 1080;
	c.memoryBudgetBytes = 256u << 20;
	st = Detector::create(model, c, det);
	EXPECT_EQ(st.code(), ErrorCode::OutOfMemory) << st.message();
	c.memoryBudgetBytes = 0;
	EXPECT_TRUE(Detector::create(model, c, det).ok());
}

// LDCF's filter stage is counted once per thread: on a PETS frame at resize 2, one filtered
// channel of the largest padded level (596 x 786 cells of 2 pixels) and the 40 half-size
// ones, next to the same options without filters.
TEST(DetectorConfig, RecommendedThreadsAreTheOnlineCoresAtMostFour)
{
	const long cores = sysconf(_SC_NPROCESSORS_ONLN);
	EXPECT_EQ(recommendedThreads(), int(std::clamp(cores, 1L, 4L)));
	EXPECT_EQ(DetectorConfig().threads, 1); // the library's own default stays one thread
}

TEST(DetectorConfig, MemoryEstimateCountsLdcfFiltersPerThread)
{
	const Model ldcf = test::randomLdcfModel(1);
	ModelParams acf = ldcf.params;
	acf.nFilters = acf.filterSize = 0;
	DetectorConfig c;
	c.maxWidth = 768;
	c.maxHeight = 576;
	c.resize = 2;
	const uint64_t without = estimateDetectorBytes(acf, c);
	const uint64_t one = estimateDetectorBytes(ldcf.params, c);
	c.threads = 3;
	const uint64_t three = estimateDetectorBytes(ldcf.params, c);
	const uint64_t withoutThree = estimateDetectorBytes(acf, c); // each thread's scratch too
	// (1152 + 8) / 2 + 2 + 2 * 7 rows and (1536 + 8) / 2 + 2 + 2 * 6 columns.
	const uint64_t filters = LdcfFilter::bytesFor(4, 596, 786);
	EXPECT_EQ(one - without, filters);
	EXPECT_EQ(three - withoutThree, 3 * filters);
	EXPECT_GT(withoutThree, without);
	EXPECT_GT(filters, 9u << 20); // 40 planes of 298 x 393 cells, and more
}

} // namespace
} // namespace calped
