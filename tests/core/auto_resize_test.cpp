// SPDX-License-Identifier: BSD-2-Clause
// chooseResize (calped/auto_resize.h) on a level pinhole camera, where the smallest person
// within the range is known in closed form.
#include <calped/auto_resize.h>

#include <cmath>

#include <gtest/gtest.h>

namespace {

using namespace calped;

// Level camera kEye metres up looking along world y, focal f, principal point (cx, cy): a
// person of height z at depth Y is f z / Y pixels tall with the feet on row cy + f kEye / Y.
constexpr double kEye = 2.0, kF = 500, kCx = 384, kCy = 288;
constexpr int kW = 768, kH = 576;

CameraModel levelCamera(double pitchDownDeg = 0)
{
	Eigen::Matrix3d K;
	K << kF, 0, kCx, 0, kF, kCy, 0, 0, 1;
	Eigen::Matrix3d level;
	level << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	const double a = pitchDownDeg * M_PI / 180;
	Eigen::Matrix3d pitch;
	pitch << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
	const Eigen::Matrix3d R = pitch * level;
	CameraModel camera;
	EXPECT_TRUE(CameraModel::fromPinhole(K, R, -R * Eigen::Vector3d(0, 0, kEye), LengthUnit::Metre,
					     camera)
			    .ok());
	return camera;
}

TEST(AutoResize, SmallestPersonIsAtTheRangeAndTheResizeShowsItAtModelSize)
{
	const CameraModel camera = levelCamera();
	ModelParams params; // INRIA: 100-pixel person, 8 scales per octave
	AutoResizeSettings s;
	s.range = 15;
	AutoResize r;
	ASSERT_TRUE(chooseResize(params, camera, kW, kH, s, r).ok());
	const double expected = kF * s.minPersonHeight / s.range; // 46.7 px at 15 m
	EXPECT_GE(r.smallestPersonPixels, expected - 1e-6);
	EXPECT_LT(r.smallestPersonPixels, expected * 1.05); // the foot grid steps 4 rows
	EXPECT_LE(r.distance, s.range);
	EXPECT_NEAR(r.footRow, kCy + kF * kEye / r.distance, 2.0);
	// At least the model's height, and one scale step less would not be.
	EXPECT_GE(r.resize * r.smallestPersonPixels, params.modelDsH - 1e-6);
	EXPECT_LT(r.resize / std::exp2(1.0 / params.nPerOct) * r.smallestPersonPixels, params.modelDsH);
	EXPECT_NEAR(std::log2(r.resize) * params.nPerOct, std::round(std::log2(r.resize) * params.nPerOct),
		    1e-9);
}

TEST(AutoResize, NearerRangeNeedsLessAndTheResultIsClamped)
{
	const CameraModel camera = levelCamera();
	ModelParams params;
	AutoResizeSettings s;
	AutoResize near, far;
	s.range = 6; // people at least 117 px tall: no upscaling needed
	ASSERT_TRUE(chooseResize(params, camera, kW, kH, s, near).ok());
	EXPECT_EQ(near.resize, s.minResize);
	s.range = 100; // 7 px at 100 m: far beyond maxResize
	ASSERT_TRUE(chooseResize(params, camera, kW, kH, s, far).ok());
	EXPECT_EQ(far.resize, s.maxResize);
	EXPECT_LT(far.smallestPersonPixels, near.smallestPersonPixels);
}

TEST(AutoResize, RefusesCamerasAndSettingsWithoutAnswer)
{
	ModelParams params;
	AutoResizeSettings s;
	AutoResize r;
	// Pitched up 60 degrees: the whole frame is sky.
	EXPECT_FALSE(chooseResize(params, levelCamera(-60), kW, kH, s, r).ok());
	EXPECT_FALSE(chooseResize(params, CameraModel(), kW, kH, s, r).ok());
	s.range = 0.5; // nobody stands this close in view
	const Status st = chooseResize(params, levelCamera(), kW, kH, s, r);
	EXPECT_FALSE(st.ok());
	EXPECT_NE(std::string(st.message()).find("no person"), std::string::npos) << st.message();
	s.range = 30;
	s.minResize = 3;
	s.maxResize = 2;
	EXPECT_FALSE(chooseResize(params, levelCamera(), kW, kH, s, r).ok());
}

} // namespace
