// SPDX-License-Identifier: BSD-2-Clause
// Self-calibration on synthetic people (fixed seeds): recovery within tolerances, each
// verdict on the input that should give it, the collector's filters, the YAML round trip.
#include <cmath>

#include <gtest/gtest.h>

#include <calped/self_calibration.h>

#include "synthetic_people.h"

namespace calped {
namespace {

using selfcal_test::SceneConfig;
using selfcal_test::calibrate;
using selfcal_test::makeObservations;

constexpr double kDegree = M_PI / 180;

TEST(SelfCalibration, RecoversATiltedCameraWithOutliers)
{
	SceneConfig scene;
	scene.focal = 1000;
	scene.tilt = 30 * kDegree;
	scene.roll = 0.03;
	scene.height = 6;
	scene.people = 3000;
	scene.outlierFraction = 0.2;
	SelfCalibrationResult r;
	ASSERT_EQ(calibrate(makeObservations(scene), scene, r), SelfCalibrationVerdict::Ok) << r.message;
	CameraParameters truth;
	ASSERT_TRUE(cameraParameters(selfcal_test::sceneCamera(scene), r.principalU, truth));
	EXPECT_NEAR(r.focal.value / 1000, 1, 0.08);
	EXPECT_NEAR(r.tilt.value, scene.tilt, 1.5 * kDegree);
	EXPECT_NEAR(r.roll.value, 0.03, 0.5 * kDegree);
	EXPECT_NEAR(r.height.value / 6, 1, 0.05);
	EXPECT_NEAR(r.horizonRow, truth.horizonRow, 15);
	// Outliers are found: about 20% of the boxes are not used.
	EXPECT_LT(r.inliers, int(0.9 * r.observations));
	EXPECT_GT(r.inliers, int(0.6 * r.observations));
	// The uncertainty covers the error (3 sd).
	EXPECT_LT(std::abs(r.height.value - 6), 3 * r.height.sd);
	EXPECT_LT(std::abs(r.focal.value - 1000), 3 * r.focal.sd);
	// The camera it makes has those parameters.
	CameraParameters estimated;
	ASSERT_TRUE(cameraParameters(r.camera, r.principalU, estimated));
	EXPECT_NEAR(estimated.focal, r.focal.value, 1e-6);
	EXPECT_NEAR(estimated.tilt, r.tilt.value, 1e-9);
	EXPECT_NEAR(estimated.height, r.height.value, 1e-9);
	EXPECT_NEAR(estimated.horizonRow, r.horizonRow, 1e-6);
}

TEST(SelfCalibration, LevelCameraGivesHeightAndHorizonButSaysFocalIsWeak)
{
	SceneConfig scene;
	scene.tilt = 0;
	scene.height = 3;
	scene.people = 1000;
	scene.outlierFraction = 0.2;
	SelfCalibrationResult r;
	ASSERT_EQ(calibrate(makeObservations(scene), scene, r), SelfCalibrationVerdict::Ok) << r.message;
	EXPECT_NEAR(r.height.value / 3, 1, 0.03);
	EXPECT_NEAR(r.horizonRow, 359.5, 5);
	EXPECT_GT(r.focal.sd, 0.2 * r.focal.value);
	EXPECT_NE(r.message.find("weakly determined"), std::string::npos) << r.message;
}

TEST(SelfCalibration, TooFewPeople)
{
	SceneConfig scene;
	scene.people = 20;
	SelfCalibrationResult r;
	EXPECT_EQ(calibrate(makeObservations(scene), scene, r), SelfCalibrationVerdict::TooFewPeople);
	EXPECT_NE(r.message.find("too few people"), std::string::npos) << r.message;
	EXPECT_FALSE(r.camera.valid());
	// No people at all.
	SelfCalibrator empty{ SelfCalibrationConfig() };
	EXPECT_EQ(empty.estimate(r), SelfCalibrationVerdict::TooFewPeople);
}

TEST(SelfCalibration, OnePersonStandingStill)
{
	SceneConfig scene;
	scene.people = 200;
	std::vector<PersonObservation> obs = makeObservations(scene);
	for (PersonObservation &o : obs) { // the same person, box jitter of a pixel
		const double jitter = double(o.frame % 5) - 2;
		o.footU = float(600 + jitter);
		o.footV = float(500 + jitter);
		o.headV = float(380 - jitter);
	}
	SelfCalibrationResult r;
	EXPECT_EQ(calibrate(obs, scene, r), SelfCalibrationVerdict::OnePlace) << r.message;
	EXPECT_NE(r.message.find("one place"), std::string::npos) << r.message;
	EXPECT_FALSE(r.camera.valid());
}

TEST(SelfCalibration, PeopleAtOneDistance)
{
	SceneConfig scene;
	scene.people = 3000;
	std::vector<PersonObservation> obs;
	for (const PersonObservation &o : makeObservations(scene))
		if (o.footV > 480 && o.footV < 520) // a band 40 px high: one distance
			obs.push_back(o);
	ASSERT_GT(obs.size(), 60u);
	SelfCalibrationResult r;
	EXPECT_EQ(calibrate(obs, scene, r), SelfCalibrationVerdict::TooLittleDepthSpread) << r.message;
	EXPECT_FALSE(r.camera.valid());
}

TEST(SelfCalibration, CameraLookingStraightDown)
{
	SceneConfig scene;
	scene.tilt = 89.5 * kDegree;
	scene.height = 8;
	scene.people = 600;
	scene.boxesSpanHeadAndFoot = true;
	SelfCalibrationResult r;
	EXPECT_EQ(calibrate(makeObservations(scene), scene, r), SelfCalibrationVerdict::LookingStraightDown)
		<< r.message;
	EXPECT_NE(r.message.find("straight down"), std::string::npos) << r.message;
	EXPECT_FALSE(r.camera.valid());
}

TEST(SelfCalibration, CameraMovingDuringCollection)
{
	// The camera tilts 6 degrees further down half-way through: the observations' rows move.
	SceneConfig scene;
	scene.people = 600;
	std::vector<PersonObservation> obs = makeObservations(scene);
	SceneConfig moved = scene;
	moved.tilt += 6 * kDegree;
	moved.seed = 2;
	for (PersonObservation o : makeObservations(moved)) {
		o.frame += 100000;
		obs.push_back(o);
	}
	SelfCalibrationResult r;
	EXPECT_EQ(calibrate(obs, scene, r), SelfCalibrationVerdict::CameraMoving) << r.message;
	EXPECT_NE(r.message.find("camera moved"), std::string::npos) << r.message;
	EXPECT_FALSE(r.camera.valid());
	// Either half alone calibrates: it is the move that is refused.
	std::vector<PersonObservation> first(obs.begin(), obs.begin() + long(obs.size() / 2));
	EXPECT_EQ(calibrate(first, scene, r), SelfCalibrationVerdict::Ok) << r.message;
}

TEST(SelfCalibrator, KeepsConfidentWholeUprightBoxes)
{
	SelfCalibrationConfig config;
	config.maxObservations = 16;
	SelfCalibrator c(config);
	ASSERT_TRUE(c.status().ok());
	Detection good;
	good.x = 100, good.y = 100, good.w = 41, good.h = 100, good.score = 80;
	Detection weak = good, cut = good, wide = good, small = good;
	weak.score = 30;
	cut.x = 0.5f;  // touches the left border
	wide.w = 100;  // not an upright person
	small.h = 10, small.w = 4.1f;
	const Detection frame[] = { good, weak, cut, wide, small };
	c.add(frame, 5, 640, 480, 7);
	ASSERT_EQ(c.size(), 1);
	EXPECT_FLOAT_EQ(c.observation(0).footU, 120.5f);
	EXPECT_FLOAT_EQ(c.observation(0).footV, 200);
	EXPECT_FLOAT_EQ(c.observation(0).headV, 100);
	EXPECT_EQ(c.observation(0).frame, 7u);
	// Bottom border cut-off.
	Detection low = good;
	low.y = 480 - 100 - 1;
	c.add(&low, 1, 640, 480, 8);
	EXPECT_EQ(c.size(), 1);
	// The ring keeps the newest maxObservations.
	for (int i = 0; i < 40; i++)
		c.add(&good, 1, 640, 480, uint64_t(10 + i));
	EXPECT_EQ(c.size(), 16);
	EXPECT_EQ(c.observation(0).frame, 10u + 40 - 16);
	EXPECT_EQ(c.observation(15).frame, 49u);
	// A new image size is a new camera; reset() forgets too.
	c.add(&good, 1, 800, 600, 60);
	EXPECT_EQ(c.size(), 1);
	c.reset();
	EXPECT_EQ(c.size(), 0);
}

TEST(SelfCalibrator, RefusesBadSettings)
{
	SelfCalibrationConfig config;
	config.maxObservations = 3;
	EXPECT_FALSE(SelfCalibrator(config).status().ok());
	config = SelfCalibrationConfig();
	config.personHeight = -1;
	SelfCalibrator c(config);
	EXPECT_NE(std::string(c.status().message()).find("personHeight"), std::string::npos);
	SelfCalibrationResult r;
	EXPECT_NE(c.estimate(r), SelfCalibrationVerdict::Ok);
}

TEST(SelfCalibration, OpenCvYamlRoundTrip)
{
	CameraModel camera;
	ASSERT_TRUE(makeSelfCalibratedCamera(1234.5, 0.3, -0.02, 7.25, 383.5, 287.5, camera).ok());
	std::string yaml;
	ASSERT_TRUE(formatOpenCvYaml(camera, "a comment\nover two lines", yaml).ok());
	CameraModel loaded;
	const Status st = loadOpenCvYaml(yaml.data(), yaml.size(), "round-trip.yaml", loaded);
	ASSERT_TRUE(st.ok()) << st.message() << "\n" << yaml;
	EXPECT_TRUE(loaded.projection().isApprox(camera.projection(), 1e-12));
	CameraParameters p;
	ASSERT_TRUE(cameraParameters(loaded, 383.5, p));
	EXPECT_NEAR(p.focal, 1234.5, 1e-9);
	EXPECT_NEAR(p.tilt, 0.3, 1e-12);
	EXPECT_NEAR(p.roll, -0.02, 1e-12);
	EXPECT_NEAR(p.height, 7.25, 1e-12);
	// A person 1.7 m tall at row 400 has the same pixel height in both.
	EXPECT_NEAR(loaded.pixelHeight(Eigen::Vector2d(383.5, 400), 1.7),
		    camera.pixelHeight(Eigen::Vector2d(383.5, 400), 1.7), 1e-9);
	// The same parameters from a bare projection matrix.
	CameraModel bare;
	ASSERT_TRUE(CameraModel::fromProjection(camera.projection(), LengthUnit::Metre, bare).ok());
	ASSERT_TRUE(cameraParameters(bare, 383.5, p));
	EXPECT_NEAR(p.focal, 1234.5, 1e-6);
	EXPECT_NEAR(p.tilt, 0.3, 1e-9);
	EXPECT_NEAR(p.roll, -0.02, 1e-9);
}

TEST(SelfCalibration, MakeCameraRefusesStraightDownAndBadValues)
{
	CameraModel camera;
	EXPECT_FALSE(makeSelfCalibratedCamera(1000, M_PI / 2, 0, 5, 0, 0, camera).ok());
	EXPECT_FALSE(makeSelfCalibratedCamera(-1, 0.2, 0, 5, 0, 0, camera).ok());
	EXPECT_FALSE(makeSelfCalibratedCamera(1000, 0.2, 0, 0, 0, 0, camera).ok());
	EXPECT_FALSE(camera.valid());
}

} // namespace
} // namespace calped
