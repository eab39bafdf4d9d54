// SPDX-License-Identifier: BSD-2-Clause
// Direct linear transform on synthetic cameras: exact recovery, noise, degenerate inputs.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

// Random points in a volume the pitched camera sees (x in [-8, 8], y in [8, 40], z in
// [0, 2.5] metres), projected exactly.
std::vector<PointCorrespondence> pitchedPoints(size_t n, double noisePx, unsigned seed)
{
	const CameraModel cam = pitchedCamera();
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> ux(-8, 8), uy(8, 40), uz(0, 2.5);
	std::normal_distribution<double> noise(0.0, noisePx > 0 ? noisePx : 1.0);
	std::vector<PointCorrespondence> pts(n);
	for (PointCorrespondence &p : pts) {
		p.world = Eigen::Vector3d(ux(rng), uy(rng), uz(rng));
		p.image = cam.project(p.world);
		if (noisePx > 0)
			p.image += Eigen::Vector2d(noise(rng), noise(rng));
	}
	return pts;
}

TEST(Dlt, RecoversSyntheticCameraExactly)
{
	for (size_t n : { 6, 7, 12, 100 }) {
		const std::vector<PointCorrespondence> pts = pitchedPoints(n, 0, 7);
		DltResult r;
		Status st = estimateProjectionDlt(pts.data(), pts.size(), r);
		ASSERT_TRUE(st.ok()) << st.message();
		// Same normalisation (depth scale, det M > 0): P itself is recovered, not only
		// up to scale.
		const Matrix34d ref = pitchedCamera().projection();
		EXPECT_LT((r.projection - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff(), 1e-9)
			<< n << " points";
		EXPECT_LT(r.rmsError, 1e-6) << n << " points";
		EXPECT_LT(r.maxError, 1e-6) << n << " points";
	}
}

TEST(Dlt, MillimetreWorldGivesTheSameCamera)
{
	std::vector<PointCorrespondence> pts = pitchedPoints(30, 0, 3);
	for (PointCorrespondence &p : pts)
		p.world *= 1000.0;
	DltResult r;
	ASSERT_TRUE(estimateProjectionDlt(pts.data(), pts.size(), r).ok());
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromProjection(r.projection, LengthUnit::Millimetre, m).ok());
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-6);
	EXPECT_LT(r.rmsError, 1e-6);
}

TEST(Dlt, NoisyPoints)
{
	const std::vector<PointCorrespondence> pts = pitchedPoints(200, 0.5, 11);
	DltResult r;
	ASSERT_TRUE(estimateProjectionDlt(pts.data(), pts.size(), r).ok());
	// The residual of a least-squares fit is a little below the noise; the camera is close.
	EXPECT_GT(r.rmsError, 0.4);
	EXPECT_LT(r.rmsError, 0.8);
	EXPECT_LT(r.maxError, 3.0);
	CameraModel m;
	ASSERT_TRUE(CameraModel::fromProjection(r.projection, LengthUnit::Metre, m).ok());
	EXPECT_LT((m.centre() - Eigen::Vector3d(0, 0, 10)).norm(), 0.3);
	// Heights across the image within 1%.
	const CameraModel ref = pitchedCamera();
	for (double v = 100; v <= 700; v += 100)
		for (double u = 100; u <= 1200; u += 200) {
			const Eigen::Vector2d foot(u, v);
			const double px = ref.pixelHeight(foot, 1.8);
			EXPECT_NEAR(m.worldHeight(foot, Eigen::Vector2d(u, v - px)), 1.8, 0.018);
		}
	std::printf("    200 points, 0.5 px noise: RMS %.3f px, max %.3f px, centre error %.3f m\n",
		    r.rmsError, r.maxError, (m.centre() - Eigen::Vector3d(0, 0, 10)).norm());
}

TEST(Dlt, TooFewPoints)
{
	const std::vector<PointCorrespondence> pts = pitchedPoints(5, 0, 1);
	DltResult r;
	Status st = estimateProjectionDlt(pts.data(), pts.size(), r);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_STREQ(st.message(),
		     "InvalidArgument: the DLT needs at least 6 correspondences, got 5");
	EXPECT_EQ(estimateProjectionDlt(nullptr, 10, r).code(), ErrorCode::InvalidArgument);
}

TEST(Dlt, CoplanarWorldPoints)
{
	std::vector<PointCorrespondence> pts = pitchedPoints(40, 0, 2);
	for (PointCorrespondence &p : pts) { // all on the ground
		p.world.z() = 0;
		p.image = pitchedCamera().project(p.world);
	}
	DltResult r;
	Status st = estimateProjectionDlt(pts.data(), pts.size(), r);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("coplanar"), std::string::npos) << st.message();

	// A tilted plane is just as degenerate.
	for (PointCorrespondence &p : pts) {
		p.world.z() = 0.3 * p.world.x() - 0.1 * p.world.y() + 4;
		p.image = pitchedCamera().project(p.world);
	}
	st = estimateProjectionDlt(pts.data(), pts.size(), r);
	EXPECT_NE(std::string(st.message()).find("coplanar"), std::string::npos) << st.message();
}

TEST(Dlt, OtherDegenerateInputs)
{
	std::vector<PointCorrespondence> pts = pitchedPoints(10, 0, 4);
	DltResult r;
	std::vector<PointCorrespondence> same(8, pts[0]);
	Status st = estimateProjectionDlt(same.data(), same.size(), r);
	EXPECT_NE(std::string(st.message()).find("coincide"), std::string::npos) << st.message();

	// Ground points plus points on one line through the camera centre (all seen at one
	// pixel): not coplanar, yet P is not determined (Hartley & Zisserman 7.1.1).
	std::vector<PointCorrespondence> ray;
	const CameraModel cam = pitchedCamera();
	for (double x : { -6.0, 0.0, 6.0 })
		for (double y : { 10.0, 20.0, 30.0 }) {
			PointCorrespondence p;
			p.world = Eigen::Vector3d(x, y, 0);
			p.image = cam.project(p.world);
			ray.push_back(p);
		}
	for (double s : { 0.3, 0.5, 0.7 }) {
		PointCorrespondence p;
		p.world = Eigen::Vector3d(0, 0, 10) + s * Eigen::Vector3d(2, 20, -10);
		p.image = cam.project(Eigen::Vector3d(2, 20, 0));
		ray.push_back(p);
	}
	st = estimateProjectionDlt(ray.data(), ray.size(), r);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::string(st.message()).find("rank < 11"), std::string::npos) << st.message();

	pts[3].world.y() = std::nan("");
	st = estimateProjectionDlt(pts.data(), pts.size(), r);
	EXPECT_STREQ(st.message(), "InvalidArgument: correspondence 4 is not finite");
}

} // namespace
} // namespace calped
