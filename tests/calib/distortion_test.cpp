// SPDX-License-Identifier: BSD-2-Clause
// Tsai and OpenCV lens distortion: hand-computed values and round trips.
#include <cmath>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// 640 x 480 Tsai camera: 0.01 mm pixels, centre (320, 240), level, 5 m up.
TsaiCamera smallTsai(double kappa1)
{
	TsaiCamera c;
	c.width = 640;
	c.height = 480;
	c.ncx = c.nfx = 640;
	c.dx = c.dy = c.dpx = c.dpy = 0.01;
	c.focal = 8;
	c.kappa1 = kappa1;
	c.cx = 320;
	c.cy = 240;
	c.sx = 1;
	c.rx = M_PI / 2; // optical axis along world +y, image down = world -z
	c.ty = 5000;	  // X_cam = R X_world + T with the centre at (0, 0, 5000) mm
	return c;
}

TEST(Distortion, TsaiHandComputed)
{
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromTsai(smallTsai(1e-3), LengthUnit::Millimetre, m).ok());
	ASSERT_EQ(m.distortionModel(), DistortionModel::TsaiRadial);
	ASSERT_NEAR(m.centre().z(), 5.0, 1e-12);
	// Pixel (420, 240): Xd = 100 px * 0.01 mm = 1 mm, Xu = Xd (1 + 1e-3 * 1) = 1.001 mm.
	const Vector2d u = m.undistort(Vector2d(420, 240));
	EXPECT_NEAR(u.x(), 420.1, 1e-12);
	EXPECT_NEAR(u.y(), 240.0, 1e-12);
	// (320 + 300, 240 + 400): rd = 5 mm, factor 1 + 1e-3 * 25 = 1.025.
	const Vector2d v = m.undistort(Vector2d(620, 640));
	EXPECT_NEAR(v.x(), 320 + 300 * 1.025, 1e-12);
	EXPECT_NEAR(v.y(), 240 + 400 * 1.025, 1e-12);
	EXPECT_NEAR(m.distort(Vector2d(420.1, 240)).x(), 420.0, 1e-9);
	EXPECT_EQ(m.undistort(Vector2d(320, 240)), Vector2d(320, 240));
}

TEST(Distortion, TsaiRoundTrip)
{
	for (double k : { 5e-3, 1e-3, -1e-3, -2e-3 }) {
		CameraModel m;
		ASSERT_TRUE(CameraModel::fromTsai(smallTsai(k), LengthUnit::Millimetre, m).ok());
		double worst = 0;
		for (double y = 0; y <= 480; y += 20)
			for (double x = 0; x <= 640; x += 20) {
				const Vector2d p(x, y);
				worst = std::max(worst, (m.distort(m.undistort(p)) - p).norm());
			}
		EXPECT_LT(worst, 1e-9) << "kappa1 " << k;
	}
}

TEST(Distortion, TsaiNegativeKappaBeyondTurningRadius)
{
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromTsai(smallTsai(-1e-2), LengthUnit::Millimetre, m).ok());
	// ru = rd (1 - 0.01 rd^2) peaks at rd = 5.77 mm, ru = 3.85 mm: farther has no pixel.
	EXPECT_TRUE(std::isnan(m.distort(Vector2d(320 + 500, 240)).x()));
	EXPECT_TRUE(std::isfinite(m.distort(Vector2d(320 + 300, 240)).x()));
}

TEST(Distortion, TsaiWorldToPixelUsesDistortion)
{
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromTsai(smallTsai(1e-3), LengthUnit::Millimetre, m).ok());
	// Ground point (1, 10) m: undistorted 320 + 800 * 1 / 10 = 400, 240 + 800 * 5 / 10 = 640.
	const Vector3d X(1, 10, 0);
	const Vector2d point = m.project(X);
	EXPECT_NEAR(point.x(), 400, 1e-9);
	EXPECT_NEAR(point.y(), 640, 1e-9);
	const Vector2d pixel = m.worldToPixel(X);
	EXPECT_LT((pixel - Vector2d(320, 240)).norm(), (point - Vector2d(320, 240)).norm());
	Vector2d g;
	ASSERT_TRUE(m.pixelToGround(pixel, g));
	EXPECT_NEAR(g.x(), 1.0, 1e-9);
	EXPECT_NEAR(g.y(), 10.0, 1e-9);
	// Box heights through distortion invert each other on the vertical through the centre.
	const Vector2d foot = m.worldToPixel(Vector3d(0, 10, 0));
	const double px = m.boxPixelHeight(foot, 1.8);
	EXPECT_NEAR(m.boxWorldHeight(foot, Vector2d(foot.x(), foot.y() - px)), 1.8, 1e-9);
}

TEST(Distortion, OpenCvHandComputed)
{
	Eigen::Matrix3d K;
	K << 1000, 0, 500, 0, 1000, 500, 0, 0, 1;
	OpenCvDistortion d;
	d.k1 = 0.1;
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromOpenCv(K, calib_test::pitchedR(), calib_test::pitchedT(), d,
					    LengthUnit::Metre, m)
			    .ok());
	ASSERT_EQ(m.distortionModel(), DistortionModel::OpenCv);
	// x = 0.1: xd = 0.1 (1 + 0.1 * 0.01) = 0.1001.
	EXPECT_NEAR(m.distort(Vector2d(600, 500)).x(), 600.1, 1e-9);
	EXPECT_NEAR(m.undistort(Vector2d(600.1, 500)).x(), 600.0, 1e-9);

	OpenCvDistortion t;
	t.p1 = 0.01;
	ASSERT_TRUE(CameraModel::fromOpenCv(K, calib_test::pitchedR(), calib_test::pitchedT(), t,
					    LengthUnit::Metre, m)
			    .ok());
	// x = 0.1, y = 0: xd = x + p2 (..) = 0.1, yd = p1 (r^2 + 2 y^2) = 0.01 * 0.01.
	const Vector2d p = m.distort(Vector2d(600, 500));
	EXPECT_NEAR(p.x(), 600.0, 1e-9);
	EXPECT_NEAR(p.y(), 500.1, 1e-9);
}

TEST(Distortion, OpenCvRoundTripStrong)
{
	// Town Centre-like coefficients (k2 = 4.7) over a 1920 x 1080 image.
	Eigen::Matrix3d K;
	K << 2696.36, 0, 959.5, 0, 2696.36, 539.5, 0, 0, 1;
	OpenCvDistortion d;
	d.k1 = -0.6015;
	d.k2 = 4.702;
	d.p1 = -0.000475;
	d.p2 = -0.00782;
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromOpenCv(K, calib_test::pitchedR(), calib_test::pitchedT(), d,
					    LengthUnit::Metre, m)
			    .ok());
	double worst = 0;
	for (double y = 0; y <= 1080; y += 40)
		for (double x = 0; x <= 1920; x += 40) {
			const Vector2d p(x, y);
			const Vector2d u = m.undistort(p);
			ASSERT_TRUE(u.allFinite()) << x << "," << y;
			worst = std::max(worst, (m.distort(u) - p).norm());
		}
	EXPECT_LT(worst, 1e-8);
}

TEST(Distortion, NoneIsIdentity)
{
	const CameraModel m = calib_test::pitchedCamera();
	EXPECT_EQ(m.distortionModel(), DistortionModel::None);
	EXPECT_EQ(m.undistort(Vector2d(12.5, 99)), Vector2d(12.5, 99));
	EXPECT_EQ(m.distort(Vector2d(12.5, 99)), Vector2d(12.5, 99));
	EXPECT_EQ(m.boxPixelHeight(Vector2d(640, 600), 1.8), m.pixelHeight(Vector2d(640, 600), 1.8));
}

} // namespace
} // namespace calped
