// SPDX-License-Identifier: BSD-2-Clause
// Self-calibration on PETS 2009 frames through the real detector (generic method, resize 2):
// a few frames are too few people; frames panned synthetically (a crop window that jumps
// half-way through) are a moving camera. Skips without data/pets/frames or the INRIA model.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <calped/calped.h>
#include <calped/self_calibration.h>

#include "test_data.h"

namespace calped {
namespace {

struct PetsRun {
	Model model;
	std::unique_ptr<Detector> detector;
	bool ready = false;
};

// The detector for frames of w x h, or a skip message.
std::string prepare(PetsRun &run, int w, int h)
{
	if (test::petsFrame(1).empty())
		return "PETS frames not found (data/pets/frames; scripts/fetch-pets.sh)";
	const std::string blob = test::inriaModelBlob();
	std::vector<uint8_t> bytes;
	if (blob.empty() || !test::readFile(blob, bytes))
		return "INRIA model not available (../shared and calped-convert)";
	if (!loadModel(bytes.data(), bytes.size(), run.model).ok())
		return "INRIA model does not load";
	DetectorConfig config;
	config.maxWidth = w;
	config.maxHeight = h;
	config.resize = 2;
	config.method = DetectionMethod::Generic;
	const Status st = Detector::create(run.model, config, run.detector);
	return st.ok() ? "" : std::string("detector: ") + st.message();
}

// Frames 1..frames, each cropped to w x h at (0, 0), from frame `panFrame` (1-based) on at
// (dx, dy): the camera panned there.
void collect(PetsRun &run, SelfCalibrator &calibrator, int frames, int w, int h, int panFrame,
	     int dx, int dy)
{
	std::vector<uint8_t> crop(size_t(w) * h * 3);
	for (int k = 0; k < frames; k++) {
		test::RgbImage image;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k + 1), image)) << "frame " << k + 1;
		const int x0 = k + 1 >= panFrame ? dx : 0, y0 = k + 1 >= panFrame ? dy : 0;
		ASSERT_LE(x0 + w, image.width);
		ASSERT_LE(y0 + h, image.height);
		for (int y = 0; y < h; y++)
			std::copy_n(&image.pixels[(size_t(y0 + y) * image.width + x0) * 3], size_t(w) * 3,
				    &crop[size_t(y) * w * 3]);
		Detections dets;
		ASSERT_TRUE(run.detector->detect(ImageView::rgb8(crop.data(), w, h), dets).ok());
		calibrator.add(dets.items, size_t(dets.count), w, h, uint64_t(k));
	}
}

TEST(SelfCalibrationPets, AFewFramesAreTooFewPeople)
{
	PetsRun run;
	const std::string skip = prepare(run, 768, 576);
	if (!skip.empty())
		GTEST_SKIP() << skip;
	SelfCalibrator calibrator{ SelfCalibrationConfig() };
	collect(run, calibrator, 4, 768, 576, 1, 0, 0);
	SelfCalibrationResult r;
	EXPECT_EQ(calibrator.estimate(r), SelfCalibrationVerdict::TooFewPeople) << r.message;
	EXPECT_FALSE(r.camera.valid());
	std::printf("4 frames: %d observations: %s\n", calibrator.size(), r.message.c_str());
}

TEST(SelfCalibrationPets, PannedFramesAreAMovingCamera)
{
	if (test::petsFrame(50).empty())
		GTEST_SKIP() << "needs PETS frames 1-50 (data/pets/frames)";
	PetsRun run;
	const int w = 640, h = 420; // pans 128 px right and 156 px down after frame 25
	const std::string skip = prepare(run, w, h);
	if (!skip.empty())
		GTEST_SKIP() << skip;
	SelfCalibrator calibrator{ SelfCalibrationConfig() };
	collect(run, calibrator, 50, w, h, 26, 128, 156);
	SelfCalibrationResult r;
	EXPECT_EQ(calibrator.estimate(r), SelfCalibrationVerdict::CameraMoving) << r.message;
	EXPECT_FALSE(r.camera.valid());
	std::printf("panned 50 frames: %d observations: %s\n", calibrator.size(), r.message.c_str());
}

} // namespace
} // namespace calped
