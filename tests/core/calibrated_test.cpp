// SPDX-License-Identifier: BSD-2-Clause
// The calibrated method: refused set-ups, the static gate, placed levels and rectangles,
// low cameras, and calibrated against generic detection on PETS.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <calped/calped.h>

#include "search/calibrated_plan.h"
#include "detect/detector_internals.h"
#include "synthetic.h"
#include "test_data.h"

using namespace calped;

namespace {

// A level camera 2 m above the ground looking along +y: a 2 m person is as tall in pixels
// as the distance from the principal row to their feet.
CameraModel levelCamera(double f, double cx, double cy)
{
	Eigen::Matrix3d K;
	K << f, 0, cx, 0, f, cy, 0, 0, 1;
	Eigen::Matrix3d R;
	R << 1, 0, 0, 0, 0, -1, 0, 1, 0; // camera x = world x, camera y = -world z, camera z = world y
	const Eigen::Vector3d t(0, 2.0, 0);
	CameraModel camera;
	const Status st = CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, camera);
	EXPECT_TRUE(st.ok()) << st.message();
	return camera;
}

// A 640x480 camera (focal length 500) `height` metres above the ground (world z up),
// looking along +y with its optical axis pitched down by `downDeg` degrees: the horizon
// 500 tan(downDeg) pixels above the image centre.
CameraModel groundCamera(double height, double downDeg)
{
	Eigen::Matrix3d K;
	K << 500, 0, 320, 0, 500, 240, 0, 0, 1;
	Eigen::Matrix3d level;
	level << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	// A rotation by p about the camera x axis turns the optical axis to (0, cos p, sin p)
	// in the world: down is a negative p.
	const double p = -downDeg * 3.14159265358979 / 180;
	Eigen::Matrix3d tilt;
	tilt << 1, 0, 0, 0, std::cos(p), std::sin(p), 0, -std::sin(p), std::cos(p);
	const Eigen::Matrix3d R = tilt * level;
	const Eigen::Vector3d t = -R * Eigen::Vector3d(0, 0, height);
	CameraModel camera;
	const Status st = CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, camera);
	EXPECT_TRUE(st.ok()) << st.message();
	return camera;
}

} // namespace

TEST(CalibratedDetector, ACameraThatSeesNoGroundIsRefused)
{
	// Looking up at the sky (tilted 60 degrees up, 2 m high: the horizon is 1386 rows below
	// the principal point, under the image): no window anywhere holds a standing person,
	// which is a wrong calibration, not an empty scene. The principal point is the frame's
	// centre (one outside the frame is refused earlier, as a calibration for other frames).
	Eigen::Matrix3d K;
	K << 800, 0, 320, 0, 800, 240, 0, 0, 1;
	const double up = 60.0 * M_PI / 180.0;
	Eigen::Matrix3d R; // rows: the camera's x, y (image down) and viewing axes in the world
	R << 1, 0, 0, 0, std::sin(up), -std::cos(up), 0, std::cos(up), std::sin(up);
	const Eigen::Vector3d t(0, 2.0 * std::cos(up), -2.0 * std::sin(up)); // centre (0, 0, 2)
	CameraModel camera;
	ASSERT_TRUE(CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, camera).ok());
	DetectorConfig cfg;
	cfg.maxWidth = 640;
	cfg.maxHeight = 480;
	cfg.camera = &camera;
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(test::randomModel(1), cfg, det);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("see the ground"), std::string::npos) << st.message();
	// The same camera in the generic method only reports world coordinates: allowed.
	cfg.method = DetectionMethod::Generic;
	EXPECT_TRUE(Detector::create(test::randomModel(1), cfg, det).ok());
}

TEST(CalibratedDetector, RejectsMissingCameraAndOtherFrameSizes)
{
	DetectorConfig cfg;
	cfg.maxWidth = 640;
	cfg.maxHeight = 480;
	cfg.method = DetectionMethod::Calibrated;
	std::unique_ptr<Detector> det;
	EXPECT_EQ(Detector::create(test::randomModel(1), cfg, det).code(), ErrorCode::InvalidArgument);
	const CameraModel camera = levelCamera(600, 320, 120);
	cfg.camera = &camera;
	cfg.calibrated = CalibratedSettings();
	cfg.calibrated->minPersonHeight = 2.5;
	cfg.calibrated->maxPersonHeight = 1.0;
	EXPECT_EQ(Detector::create(test::randomModel(1), cfg, det).code(), ErrorCode::InvalidArgument);
	cfg.calibrated->minPersonHeight = 1.4;
	cfg.calibrated->maxPersonHeight = 2.2;
	ASSERT_TRUE(Detector::create(test::randomModel(1), cfg, det).ok());
	const auto img = test::randomImage(1, 320, 240);
	Detections d;
	const Status st = det->detect(ImageView::rgb8(img.data(), 320, 240), d);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("640x480"), std::string::npos) << st.message();
}

TEST(CalibratedDetector, StaticGateSkipsSparseWindowsWhereNothingMoves)
{
	// A camera 3 m up looking 20 degrees down at the ground; a textured frame seen three
	// times is the background (warm-up 2), then a bright block appears in the middle.
	const CameraModel camera = groundCamera(3.0, 20);
	ASSERT_FALSE(::testing::Test::HasFailure());
	const Model model = test::randomModel(5);
	const auto ground = test::randomImage(3, 640, 480);
	auto withBlock = ground;
	for (int y = 200; y < 320; y++)
		for (int x = 300; x < 340; x++)
			for (int c = 0; c < 3; c++)
				withBlock[(size_t(y) * 640 + x) * 3 + c] = 255;
	uint64_t sparse[2][2] = {}, skipped[2][2] = {};
	for (int gate = 0; gate < 2; gate++) {
		DetectorConfig cfg;
		cfg.maxWidth = 640;
		cfg.maxHeight = 480;
		cfg.camera = &camera;
		cfg.method = DetectionMethod::Calibrated;
		cfg.staticRejection = StaticRejection();
		cfg.staticRejection->warmupFrames = 2;
		std::unique_ptr<Detector> det;
		ASSERT_TRUE(Detector::create(model, cfg, det).ok());
		DetectorInternals::of(*det).calibratedSearch.setStaticGate(gate == 1);
		Detections d;
		for (int f = 0; f < 2; f++) { // warm-up: every sparse window
			ASSERT_TRUE(det->detect(ImageView::rgb8(ground.data(), 640, 480), d).ok());
			EXPECT_EQ(det->lastStats().staticSkipped, 0u);
		}
		ASSERT_TRUE(det->detect(ImageView::rgb8(ground.data(), 640, 480), d).ok());
		sparse[gate][0] = det->lastStats().sparseWindows;
		skipped[gate][0] = det->lastStats().staticSkipped;
		ASSERT_TRUE(det->detect(ImageView::rgb8(withBlock.data(), 640, 480), d).ok());
		sparse[gate][1] = det->lastStats().sparseWindows;
		skipped[gate][1] = det->lastStats().staticSkipped;
	}
	// Without the gate nothing is skipped; with it, nothing is evaluated on the unchanged
	// frame, and on the frame with the block only the windows whose box holds enough of it.
	const uint64_t all = sparse[0][0];
	ASSERT_GT(all, 50u);
	EXPECT_EQ(skipped[0][0] + skipped[0][1], 0u);
	EXPECT_EQ(sparse[1][0], 0u);
	EXPECT_EQ(skipped[1][0], all);
	EXPECT_GT(sparse[1][1], 0u);
	EXPECT_LT(sparse[1][1] * 4, all);
	EXPECT_EQ(sparse[1][1] + skipped[1][1], all);
}

// The INRIA model and PETS view 1's calibration; false (the caller skips) when ../shared,
// the converter or the PETS frames are missing.
bool loadPets(Model &model, CameraModel &camera)
{
	const std::string shared = test::sharedDir();
	const std::string blobPath = test::inriaModelBlob();
	if (shared.empty() || blobPath.empty() || test::petsFrame(10).empty())
		return false;
	std::vector<uint8_t> blob, xml;
	EXPECT_TRUE(test::readFile(blobPath, blob));
	EXPECT_TRUE(test::readFile(shared + "/data/pets2009-s2l1/View_001.xml", xml));
	EXPECT_TRUE(loadModel(blob.data(), blob.size(), model).ok());
	EXPECT_TRUE(loadCalibration(reinterpret_cast<const char *>(xml.data()), xml.size(),
				    "View_001.xml", camera)
			    .ok());
	return true;
}

// PETS view 1 at resize 2 with this camera: the frame resized first, or (inPyramid) in
// the pyramid; the generic method.
DetectorConfig petsConfig(const CameraModel &camera, bool inPyramid)
{
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = 2.0;
	cfg.resizeAt = inPyramid ? ResizeAt::Pyramid : ResizeAt::Frame;
	cfg.camera = &camera;
	cfg.method = DetectionMethod::Generic;
	return cfg;
}

// The calibrated method with these pyramid levels, the other settings their defaults.
CalibratedSettings calibratedWith(PyramidLevels levels)
{
	CalibratedSettings s;
	s.levels = levels;
	return s;
}

TEST(CalibratedDetector, PetsFewerWindowsSameDetections)
{
	Model model;
	CameraModel camera;
	if (!loadPets(model, camera))
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	ASSERT_FALSE(::testing::Test::HasFailure());

	std::unique_ptr<Detector> generic, calibrated;
	DetectorConfig cfg = petsConfig(camera, false);
	ASSERT_TRUE(Detector::create(model, cfg, generic).ok());
	cfg.method = DetectionMethod::Calibrated;
	cfg.calibrated = calibratedWith(PyramidLevels::Toolbox);
	cfg.calibrated->boxVoting = false; // compares the windows themselves (voting moves boxes)
	ASSERT_TRUE(Detector::create(model, cfg, calibrated).ok());

	uint64_t windowsGeneric = 0, windowsCalibrated = 0;
	int strong = 0, kept = 0, levelsG = 0, levelsC = 0;
	for (int k = 1; k <= 10; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		const ImageView v = ImageView::rgb8(img.pixels.data(), img.width, img.height);
		Detections dg, dc;
		ASSERT_TRUE(generic->detect(v, dg).ok());
		std::vector<Detection> g(dg.begin(), dg.end());
		windowsGeneric += generic->lastStats().windows;
		levelsG = generic->lastStats().levels;
		ASSERT_TRUE(calibrated->detect(v, dc).ok());
		windowsCalibrated += calibrated->lastStats().windows;
		levelsC = calibrated->lastStats().levels;
		for (const Detection &c : dc) {
			EXPECT_GE(c.worldHeight, 1.4f - 1e-3f);
			EXPECT_LE(c.worldHeight, 2.2f + 1e-3f);
			EXPECT_TRUE(std::isfinite(c.groundX) && std::isfinite(c.groundY));
		}
		// Every strong generic detection of plausible height is still found.
		for (const Detection &a : g) {
			if (a.score < 30 || !(a.worldHeight >= 1.45f && a.worldHeight <= 2.15f))
				continue;
			strong++;
			for (const Detection &c : dc)
				if (std::fabs(c.x - a.x) < 1 && std::fabs(c.y - a.y) < 1 && std::fabs(c.h - a.h) < 1) {
					kept++;
					break;
				}
		}
	}
	std::printf("PETS frames 1-10, resize 2: generic %d levels %.0f windows/frame, calibrated %d levels "
		    "%.0f windows/frame; strong plausible generic detections kept %d of %d\n",
		    levelsG, windowsGeneric / 10.0, levelsC, windowsCalibrated / 10.0, kept, strong);
	EXPECT_LT(levelsC, levelsG);
	EXPECT_LT(windowsCalibrated * 3, windowsGeneric);
	EXPECT_GT(strong, 0);
	EXPECT_GE(kept, strong * 9 / 10);
}

TEST(CalibratedDetector, PlacedPyramidNeedsCalibratedMethodAndNoFrameResize)
{
	const CameraModel camera = levelCamera(600, 320, 120);
	DetectorConfig cfg;
	cfg.maxWidth = 640;
	cfg.maxHeight = 480;
	cfg.camera = &camera;
	cfg.method = DetectionMethod::Generic;
	cfg.calibrated = calibratedWith(PyramidLevels::Placed);
	std::unique_ptr<Detector> det;
	Status st = Detector::create(test::randomModel(1), cfg, det);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("method is generic"), std::string::npos) << st.message();
	cfg.method = DetectionMethod::Calibrated;
	cfg.resize = 2.0;
	cfg.resizeAt = ResizeAt::Frame;
	st = Detector::create(test::randomModel(1), cfg, det); // the frame would be resized
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("resizeAt Pyramid"), std::string::npos) << st.message();
	cfg.resizeAt = ResizeAt::Pyramid;
	EXPECT_TRUE(Detector::create(test::randomModel(1), cfg, det).ok());
	cfg.calibrated->placedLevelReach = 0;
	st = Detector::create(test::randomModel(1), cfg, det);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("placedLevelReach"), std::string::npos) << st.message();
}

float iou(const Detection &a, const Detection &b)
{
	const float w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
	const float h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
	if (w <= 0 || h <= 0)
		return 0;
	return w * h / (a.w * a.h + b.w * b.h - w * h);
}

// Detections of `a` scoring at least minScore that `b` has at IoU >= 0.5.
int matched(const std::vector<Detection> &a, const std::vector<Detection> &b, float minScore,
	    int &total)
{
	int n = 0;
	for (const Detection &d : a) {
		if (d.score < minScore)
			continue;
		total++;
		for (const Detection &e : b)
			if (iou(d, e) >= 0.5f) {
				n++;
				break;
			}
	}
	return n;
}

// Both detectors over PETS frames 1..frames: the same sparse windows and the same
// detections, bit for bit. Counts the detections, and the sparse windows `b` skipped.
void expectSameOnPets(Detector &a, Detector &b, int frames, int &detections, uint64_t &skipped)
{
	detections = 0;
	skipped = 0;
	for (int k = 1; k <= frames; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		const ImageView v = ImageView::rgb8(img.pixels.data(), img.width, img.height);
		Detections da, db;
		ASSERT_TRUE(a.detect(v, da).ok());
		ASSERT_TRUE(b.detect(v, db).ok());
		ASSERT_EQ(a.lastStats().sparseWindows, b.lastStats().sparseWindows) << "frame " << k;
		ASSERT_EQ(da.count, db.count) << "frame " << k;
		for (int i = 0; i < da.count; i++) {
			EXPECT_EQ(da.items[i].x, db.items[i].x);
			EXPECT_EQ(da.items[i].y, db.items[i].y);
			EXPECT_EQ(da.items[i].h, db.items[i].h);
			EXPECT_EQ(da.items[i].score, db.items[i].score) << "frame " << k << " detection " << i;
		}
		detections += da.count;
		skipped += b.lastStats().staticSkipped;
	}
}

TEST(CalibratedDetector, PetsRectanglesGiveTheSameDetections)
{
	// With placed levels each pass demands the rectangles around what its windows read:
	// the detections must be those of the plan's whole bands demanded once, exactly.
	// Without static rejection, and with it and its gate of the sparse grid (a short
	// warm-up, so most frames are gated).
	Model model;
	CameraModel camera;
	if (!loadPets(model, camera))
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	ASSERT_FALSE(::testing::Test::HasFailure());
	for (bool gate : { false, true }) {
		SCOPED_TRACE(gate ? "static gate" : "no gate");
		DetectorConfig cfg = petsConfig(camera, true);
		cfg.method = DetectionMethod::Calibrated;
		if (gate) {
			cfg.staticRejection = StaticRejection();
			cfg.staticRejection->warmupFrames = 3;
		}
		std::unique_ptr<Detector> fixed, rects;
		ASSERT_TRUE(Detector::create(model, cfg, fixed).ok());
		ASSERT_TRUE(Detector::create(model, cfg, rects).ok());
		ASSERT_TRUE(DetectorInternals::of(*rects).calibratedSearch.rectsPerFrame());
		DetectorInternals::of(*fixed).calibratedSearch.setRectsPerFrame(false);
		int detections = 0;
		uint64_t skipped = 0;
		expectSameOnPets(*fixed, *rects, 10, detections, skipped);
		ASSERT_FALSE(::testing::Test::HasFatalFailure());
		const long computed = DetectorInternals::of(*rects).pyramid.rectsComputed;
		std::printf("PETS frames 1-10, placed levels%s: %d detections either way; %llu sparse "
			    "windows skipped; %ld rectangles computed\n",
			    gate ? ", static gate" : "", detections, (unsigned long long)skipped, computed);
		EXPECT_GT(detections, 0);
		if (gate) {
			EXPECT_GT(skipped, 0u);
		} else {
			EXPECT_EQ(skipped, 0u);
		}
		EXPECT_GT(computed, 0); // the rectangle path ran
		// The whole bands: one demand a frame, a rectangle or two per computed level.
		EXPECT_LE(DetectorInternals::of(*fixed).pyramid.rectsComputed, 10 * 2 * 2);
	}
}

TEST(CalibratedDetector, PetsPlacedPyramidComputesLessFindsTheSamePeople)
{
	Model model;
	CameraModel camera;
	if (!loadPets(model, camera))
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	ASSERT_FALSE(::testing::Test::HasFailure());

	DetectorConfig cfg = petsConfig(camera, true);
	cfg.method = DetectionMethod::Calibrated;
	cfg.calibrated = calibratedWith(PyramidLevels::Toolbox);
	std::unique_ptr<Detector> octaves, placed;
	ASSERT_TRUE(Detector::create(model, cfg, octaves).ok());
	cfg.calibrated = calibratedWith(PyramidLevels::Placed);
	ASSERT_TRUE(Detector::create(model, cfg, placed).ok());

	int totalO = 0, totalP = 0, foundO = 0, foundP = 0, computedO = 0, computedP = 0;
	uint64_t windowsO = 0, windowsP = 0;
	for (int k = 1; k <= 10; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		const ImageView v = ImageView::rgb8(img.pixels.data(), img.width, img.height);
		Detections d;
		ASSERT_TRUE(octaves->detect(v, d).ok());
		const std::vector<Detection> o(d.begin(), d.end());
		ASSERT_TRUE(placed->detect(v, d).ok());
		const std::vector<Detection> p(d.begin(), d.end());
		computedO = octaves->lastStats().computedLevels;
		computedP = placed->lastStats().computedLevels;
		windowsO += octaves->lastStats().windows;
		windowsP += placed->lastStats().windows;
		// Strong detections of either pyramid, found by the other.
		foundO += matched(o, p, 40, totalO);
		foundP += matched(p, o, 40, totalP);
	}
	std::printf("PETS frames 1-10, resize 2 in the pyramid: computed levels %d (octaves) vs %d "
		    "(placed), windows/frame %.0f vs %.0f; strong detections found by the other: "
		    "%d of %d, %d of %d\n",
		    computedO, computedP, windowsO / 10.0, windowsP / 10.0, foundO, totalO, foundP, totalP);
	EXPECT_LT(computedP, computedO);
	EXPECT_GT(totalO, 20);
	EXPECT_GE(foundO, totalO * 9 / 10);
	EXPECT_GE(foundP, totalP * 9 / 10);
}

TEST(CalibratedDetector, LowCamerasStayCheaperThanGeneric)
{
	// Cameras 1-2 m above the ground (robots, cars), level or pitched down by 5 degrees
	// (the horizon 44 pixels above the image centre): the horizon crosses the image and
	// people of every distance overlap there. A random model with a permissive cascade
	// fires often, so dense regions open in every frame.
	const Model model = test::randomModel(11, 256);
	for (double camHeight : { 1.0, 1.5, 2.0 })
		for (double pitchDeg : { 0.0, 5.0 }) {
			const CameraModel camera = groundCamera(camHeight, pitchDeg);
			ASSERT_FALSE(::testing::Test::HasFailure());
			// Generic, calibrated, calibrated with placed pyramid levels.
			uint64_t windows[3] = {};
			double ms[3] = {};
			for (int m = 0; m < 3; m++) {
				DetectorConfig cfg;
				cfg.maxWidth = 640;
				cfg.maxHeight = 480;
				cfg.camera = &camera;
				cfg.cascadeThreshold = -2.0f;
				cfg.method = m ? DetectionMethod::Calibrated : DetectionMethod::Generic;
				if (m)
					cfg.calibrated = calibratedWith(m == 2 ? PyramidLevels::Placed
									       : PyramidLevels::Toolbox);
				std::unique_ptr<Detector> det;
				ASSERT_TRUE(Detector::create(model, cfg, det).ok());
				for (uint32_t f = 0; f < 3; f++) {
					const auto img = test::randomImage(f, 640, 480);
					Detections d;
					ASSERT_TRUE(det->detect(ImageView::rgb8(img.data(), 640, 480), d).ok());
					windows[m] += det->lastStats().windows;
					ms[m] += det->lastStats().msTotal;
				}
			}
			std::printf("camera %.1f m, pitch %.0f deg: windows/frame generic %llu, calibrated %llu "
				    "(%.1f%%), placed levels %llu; ms/frame generic %.1f, calibrated %.1f, placed "
				    "levels %.1f\n",
				    camHeight, pitchDeg, (unsigned long long)(windows[0] / 3),
				    (unsigned long long)(windows[1] / 3), 100.0 * windows[1] / windows[0],
				    (unsigned long long)(windows[2] / 3), ms[0] / 3, ms[1] / 3, ms[2] / 3);
			EXPECT_LT(windows[2] * 2, windows[0]) << camHeight << " m, " << pitchDeg << " deg";
			EXPECT_LT(windows[1] * 2, windows[0]) << camHeight << " m, " << pitchDeg << " deg";
		}
}
