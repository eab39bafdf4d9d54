// SPDX-License-Identifier: BSD-2-Clause
// Every geometric function against cases computed by hand.
#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using calib_test::levelCamera;
using calib_test::pitchedCamera;
using Eigen::Vector2d;
using Eigen::Vector3d;

// Level camera, centre (0, 0, 5), f = 1000, principal point (640, 360): a world point
// (x, y, z) is at u = 640 + 1000 x / y, v = 360 + 1000 (5 - z) / y.

TEST(Geometry, LevelProjectAndDepth)
{
	const CameraModel m = levelCamera();
	ASSERT_TRUE(m.valid());
	EXPECT_NEAR(m.centre().x(), 0.0, 1e-12);
	EXPECT_NEAR(m.centre().y(), 0.0, 1e-12);
	EXPECT_NEAR(m.centre().z(), 5.0, 1e-12);
	const Vector2d p = m.project(Vector3d(2, 20, 1.8));
	EXPECT_NEAR(p.x(), 740.0, 1e-9); // 640 + 1000 * 2 / 20
	EXPECT_NEAR(p.y(), 520.0, 1e-9); // 360 + 1000 * 3.2 / 20
	EXPECT_NEAR(m.depth(Vector3d(2, 20, 1.8)), 20.0, 1e-12);
	EXPECT_LT(m.depth(Vector3d(0, -3, 0)), 0.0);
}

TEST(Geometry, LevelHorizon)
{
	const CameraModel m = levelCamera();
	// Level optical axis: the horizon is the principal row, whatever the column.
	EXPECT_NEAR(m.horizonRow(0), 360.0, 1e-9);
	EXPECT_NEAR(m.horizonRow(1279), 360.0, 1e-9);
	const Vector3d l = m.horizon();
	EXPECT_GT(l.dot(Vector3d(640, 700, 1)), 0.0); // below: sees the ground
	EXPECT_LT(l.dot(Vector3d(640, 100, 1)), 0.0);
}

TEST(Geometry, LevelGroundPoint)
{
	const CameraModel m = levelCamera();
	Vector2d g;
	ASSERT_TRUE(m.groundPoint(Vector2d(640, 860), g)); // row 360 + 5000 / 10
	EXPECT_NEAR(g.x(), 0.0, 1e-9);
	EXPECT_NEAR(g.y(), 10.0, 1e-9);
	ASSERT_TRUE(m.groundPoint(Vector2d(1140, 860), g)); // x = 0.5 * 10
	EXPECT_NEAR(g.x(), 5.0, 1e-9);
	EXPECT_NEAR(g.y(), 10.0, 1e-9);
	ASSERT_TRUE(m.groundPoint(Vector2d(140, 385), g)); // Z = 5000 / 25 = 200, x = -0.5 * 200
	EXPECT_NEAR(g.x(), -100.0, 1e-6);
	EXPECT_NEAR(g.y(), 200.0, 1e-6);
	// On and above the horizon there is no ground in front of the camera.
	g = Vector2d(-7, -7);
	EXPECT_FALSE(m.groundPoint(Vector2d(640, 360), g));
	EXPECT_FALSE(m.groundPoint(Vector2d(640, 300), g));
	EXPECT_EQ(g, Vector2d(-7, -7));
}

TEST(Geometry, LevelHomographyRoundTrip)
{
	const CameraModel m = levelCamera();
	const Eigen::Matrix3d I = m.homography() * m.inverseHomography();
	EXPECT_LT((I - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
	// H maps ground (x, y, 1) to the image: (3, 15) is at (840, 693.33).
	const Vector2d p = (m.homography() * Vector3d(3, 15, 1)).hnormalized();
	EXPECT_NEAR(p.x(), 640 + 1000.0 * 3 / 15, 1e-9);
	EXPECT_NEAR(p.y(), 360 + 5000.0 / 15, 1e-9);
}

TEST(Geometry, LevelWorldHeight)
{
	const CameraModel m = levelCamera();
	// Foot at Z = 10 (row 860); a 1.8 m head is on row 360 + 1000 * 3.2 / 10 = 680.
	EXPECT_NEAR(m.worldHeight(Vector2d(640, 860), Vector2d(640, 680)), 1.8, 1e-12);
	// h = 5 (vb - vt) / (vb - 360): foot row 460 (Z = 50), head row 442 -> 0.9 m.
	EXPECT_NEAR(m.worldHeight(Vector2d(100, 460), Vector2d(100, 442)), 0.9, 1e-12);
	// The head's column does not matter (boxes are axis-aligned).
	EXPECT_NEAR(m.worldHeight(Vector2d(640, 860), Vector2d(700, 680)), 1.8, 1e-12);
	// Taller than the camera: head above the horizon, h = 5 * 600 / 500 = 6.
	EXPECT_NEAR(m.worldHeight(Vector2d(640, 860), Vector2d(640, 260)), 6.0, 1e-12);
	// Foot above the horizon: undefined.
	EXPECT_TRUE(std::isnan(m.worldHeight(Vector2d(640, 300), Vector2d(640, 200))));
}

TEST(Geometry, LevelPixelHeightAndHead)
{
	const CameraModel m = levelCamera();
	EXPECT_NEAR(m.pixelHeight(Vector2d(640, 860), 1.8), 180.0, 1e-9); // 1000 * 1.8 / 10
	EXPECT_NEAR(m.pixelHeight(Vector2d(300, 410), 1.75), 17.5, 1e-9); // Z = 100
	Vector2d head;
	ASSERT_TRUE(m.headPoint(Vector2d(1140, 860), 1.8, head));
	EXPECT_NEAR(head.x(), 1140.0, 1e-9); // verticals stay vertical in a level camera
	EXPECT_NEAR(head.y(), 680.0, 1e-9);
	EXPECT_TRUE(std::isnan(m.pixelHeight(Vector2d(640, 360), 1.8)));
	EXPECT_FALSE(m.headPoint(Vector2d(640, 100), 1.8, head));
}

TEST(Geometry, PixelHeightInvertsWorldHeight)
{
	const CameraModel m = pitchedCamera();
	for (double v = 100; v <= 700; v += 50) {
		for (double u = 0; u <= 1280; u += 160) {
			const Vector2d foot(u, v);
			for (double h : { 0.5, 1.4, 1.8, 2.2 }) {
				const double px = m.pixelHeight(foot, h);
				ASSERT_TRUE(std::isfinite(px));
				EXPECT_NEAR(m.worldHeight(foot, Vector2d(u, v - px)), h, 1e-9);
			}
		}
	}
}

// Pitched camera: centre (0, 0, 10), 30 degrees down, f = 1000, principal point (640, 360).
TEST(Geometry, PitchedHandCases)
{
	const CameraModel m = pitchedCamera();
	ASSERT_TRUE(m.valid());
	EXPECT_NEAR(m.centre().z(), 10.0, 1e-12);
	// The optical axis meets the ground at y = 10 / tan 30 = 17.3205 m.
	Vector2d g;
	ASSERT_TRUE(m.groundPoint(Vector2d(640, 360), g));
	EXPECT_NEAR(g.x(), 0.0, 1e-9);
	EXPECT_NEAR(g.y(), 10.0 * std::sqrt(3.0), 1e-9);
	// Ground directions vanish 30 degrees above the axis: row 360 - 1000 tan 30.
	EXPECT_NEAR(m.horizonRow(640), 360.0 - 1000.0 / std::sqrt(3.0), 1e-9);
	EXPECT_NEAR(m.horizonRow(0), m.horizonRow(1280), 1e-9); // no roll
	// The axis ray: the row looking 30 + a degrees down meets the ground at 10 / tan(30 + a).
	const double a = std::atan(140.0 / 1000.0); // row 500
	ASSERT_TRUE(m.groundPoint(Vector2d(640, 500), g));
	EXPECT_NEAR(g.y(), 10.0 / std::tan(M_PI / 6 + a), 1e-9);
	// A 1.8 m person at (0, 17.3205): head relative to the centre (0, 17.3205, -8.2), in
	// camera coordinates y = -0.5 * 17.3205 + 0.8660 * 8.2 = -1.5588, z = 15 + 4.1 = 19.1.
	const double yc = -0.5 * 10.0 * std::sqrt(3.0) + std::sqrt(3.0) / 2 * 8.2;
	const double expected = -1000.0 * yc / 19.1;
	EXPECT_NEAR(m.pixelHeight(Vector2d(640, 360), 1.8), expected, 1e-9);
	EXPECT_NEAR(m.worldHeight(Vector2d(640, 360), Vector2d(640, 360 - expected)), 1.8, 1e-12);
}

TEST(Geometry, DepthScaleAndSignNormalised)
{
	// Any non-zero multiple of P, negative included, is the same camera.
	const CameraModel ref = pitchedCamera();
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromProjection(-3.7 * ref.projection(), LengthUnit::Metre, m).ok());
	EXPECT_LT((m.projection() - ref.projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_NEAR(m.depth(Vector3d(0, 10 * std::sqrt(3.0), 0)), 20.0, 1e-9);
	EXPECT_FALSE(m.hasPinhole());
}

TEST(Geometry, InvalidModelGivesNaN)
{
	const CameraModel m;
	EXPECT_FALSE(m.valid());
	Vector2d g;
	EXPECT_FALSE(m.groundPoint(Vector2d(1, 2), g));
	EXPECT_TRUE(std::isnan(m.worldHeight(Vector2d(1, 2), Vector2d(1, 1))));
	EXPECT_TRUE(std::isnan(m.pixelHeight(Vector2d(1, 2), 1.8)));
	EXPECT_TRUE(std::isnan(m.project(Vector3d(1, 2, 3)).x()));
}

TEST(Geometry, RejectsDegenerateCameras)
{
	Matrix34d P = pitchedCamera().projection();
	CameraModel m;
	Matrix34d singular = P;
	singular.col(2) = singular.col(0) + singular.col(1); // rank-2 left block
	Status st = CameraModel::fromProjection(singular, LengthUnit::Metre, m);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("singular"), std::string::npos) << st.message();

	// Camera below the ground (z axis pointing down in the file's world).
	Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
	Matrix34d down = P;
	down.leftCols<3>() = P.leftCols<3>() * flip;
	st = CameraModel::fromProjection(down, LengthUnit::Metre, m);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("not above the ground"), std::string::npos)
		<< st.message();

	Matrix34d nan = P;
	nan(1, 1) = std::nan("");
	st = CameraModel::fromProjection(nan, LengthUnit::Metre, m);
	EXPECT_NE(std::string(st.message()).find("not finite"), std::string::npos) << st.message();

	Eigen::Matrix3d K = calib_test::pitchedK();
	K(1, 1) = -5;
	st = CameraModel::fromPinhole(K, calib_test::pitchedR(), calib_test::pitchedT(),
				      LengthUnit::Metre, m);
	EXPECT_NE(std::string(st.message()).find("focal"), std::string::npos) << st.message();
	st = CameraModel::fromPinhole(calib_test::pitchedK(), 1.1 * calib_test::pitchedR(),
				      calib_test::pitchedT(), LengthUnit::Metre, m);
	EXPECT_NE(std::string(st.message()).find("not a rotation"), std::string::npos)
		<< st.message();
	EXPECT_FALSE(m.valid()); // failures leave the output untouched
}

TEST(Geometry, UnitsConvertToMetres)
{
	// The same camera from a P acting on millimetres gives metres.
	const CameraModel ref = pitchedCamera();
	Matrix34d Pmm = ref.projection();
	Pmm.leftCols<3>() *= 0.001;
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromProjection(Pmm, LengthUnit::Millimetre, m).ok());
	EXPECT_LT((m.projection() - ref.projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Millimetre);
	EXPECT_NEAR(m.centre().z(), 10.0, 1e-9);
}

} // namespace
} // namespace calped
