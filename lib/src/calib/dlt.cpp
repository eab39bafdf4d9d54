// SPDX-License-Identifier: BSD-2-Clause
// Direct linear transform (thesis chapter 2.3; Hartley & Zisserman, algorithm 7.1): P from
// image/world correspondences, both point sets normalised first so that the SVD is well
// conditioned whatever the units.
#include <calped/calibration.h>

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

namespace calped {

namespace {

// Below these relative sizes the configuration cannot determine P.
constexpr double kPlanarTolerance = 1e-9; // smallest / largest world scatter eigenvalue
constexpr double kRankTolerance = 1e-10;  // 11th / 1st singular value of the DLT system

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Row12 = Eigen::Matrix<double, 1, 12>;

// Rotates row `a` into the upper triangular R (one step of a row-wise QR factorisation).
void foldRow(Matrix12 &R, Row12 &a)
{
	for (int j = 0; j < 12; j++) {
		if (a(j) == 0.0)
			continue;
		const double r = std::hypot(R(j, j), a(j));
		const double c = R(j, j) / r, s = a(j) / r;
		for (int k = j; k < 12; k++) {
			const double rk = R(j, k), ak = a(k);
			R(j, k) = c * rk + s * ak;
			a(k) = c * ak - s * rk;
		}
	}
}

// Similarity moving the centroid to the origin with mean distance sqrt(dim).
template<int Dim>
bool normalisation(const PointCorrespondence *points, size_t count,
		   Eigen::Matrix<double, Dim + 1, Dim + 1> &T)
{
	using Vec = Eigen::Matrix<double, Dim, 1>;
	auto get = [&](size_t i) -> Vec {
		if constexpr (Dim == 2)
			return points[i].image;
		else
			return points[i].world;
	};
	Vec centroid = Vec::Zero();
	for (size_t i = 0; i < count; i++)
		centroid += get(i);
	centroid /= static_cast<double>(count);
	double mean = 0;
	for (size_t i = 0; i < count; i++)
		mean += (get(i) - centroid).norm();
	mean /= static_cast<double>(count);
	// Relative test: rounding leaves a tiny spread around coincident points.
	if (!(mean > 1e-12 * (1.0 + centroid.norm())) || !std::isfinite(mean))
		return false;
	const double s = std::sqrt(static_cast<double>(Dim)) / mean;
	T.setIdentity();
	T.template topLeftCorner<Dim, Dim>() *= s;
	T.template topRightCorner<Dim, 1>() = -s * centroid;
	return true;
}

Status estimate(const PointCorrespondence *points, size_t count, DltResult &out)
{
	if (!points || count < 6)
		return Status::error(ErrorCode::InvalidArgument,
				     "the DLT needs at least 6 correspondences, got %zu", count);
	for (size_t i = 0; i < count; i++)
		if (!points[i].image.allFinite() || !points[i].world.allFinite())
			return Status::error(ErrorCode::InvalidArgument,
					     "correspondence %zu is not finite", i + 1);

	Eigen::Matrix3d Ti;
	Eigen::Matrix4d Tw;
	if (!normalisation<2>(points, count, Ti))
		return Status::error(ErrorCode::InvalidArgument,
				     "degenerate correspondences: all image points coincide");
	if (!normalisation<3>(points, count, Tw))
		return Status::error(ErrorCode::InvalidArgument,
				     "degenerate correspondences: all world points coincide");

	// World points on one plane leave P undetermined (a whole family fits).
	Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
	for (size_t i = 0; i < count; i++) {
		const Eigen::Vector3d X = (Tw * points[i].world.homogeneous()).head<3>();
		scatter += X * X.transpose();
	}
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter, Eigen::EigenvaluesOnly);
	const Eigen::Vector3d ev = eig.eigenvalues(); // ascending
	if (ev(0) < kPlanarTolerance * ev(2))
		return Status::error(ErrorCode::InvalidArgument,
				     "degenerate correspondences: the world points are coplanar "
				     "(or collinear); the DLT needs points off any single plane, "
				     "e.g. ground points and points at head height");

	// The 2N x 12 system A p = 0 is folded row by row into a 12 x 12 triangular R with
	// Givens rotations (A = Q R): R has A's singular values and right singular vectors, so
	// the SVD stays well conditioned and nothing here allocates.
	Matrix12 R = Matrix12::Zero();
	for (size_t i = 0; i < count; i++) {
		const Eigen::Vector3d x = Ti * points[i].image.homogeneous();
		const Eigen::RowVector4d X = (Tw * points[i].world.homogeneous()).transpose();
		// u (p3 . X) - p1 . X = 0 and v (p3 . X) - p2 . X = 0, with x normalised (w = 1).
		Row12 a = Row12::Zero();
		a.segment<4>(0) = -X;
		a.segment<4>(8) = x.x() * X;
		foldRow(R, a);
		a.setZero();
		a.segment<4>(4) = -X;
		a.segment<4>(8) = x.y() * X;
		foldRow(R, a);
	}
	Eigen::JacobiSVD<Matrix12> svd(R, Eigen::ComputeFullV);
	const Eigen::Matrix<double, 12, 1> sv = svd.singularValues();
	if (!(sv(10) > kRankTolerance * sv(0)))
		return Status::error(ErrorCode::InvalidArgument,
				     "degenerate correspondences: the DLT system has rank < 11 "
				     "(singular values %.3g ... %.3g)",
				     sv(0), sv(10));

	const Eigen::Matrix<double, 12, 1> p = svd.matrixV().col(11);
	Matrix34d Pn;
	Pn << p(0), p(1), p(2), p(3), p(4), p(5), p(6), p(7), p(8), p(9), p(10), p(11);
	Matrix34d P = Ti.inverse() * Pn * Tw;
	// Depth scale: unit third row direction, positive in front (det M > 0).
	const Eigen::Matrix3d M = P.leftCols<3>();
	double scale = 1.0 / M.row(2).norm();
	if (M.determinant() < 0.0)
		scale = -scale;
	P *= scale;
	if (!P.allFinite())
		return Status::error(ErrorCode::InvalidArgument,
				     "degenerate correspondences: no finite solution");

	double sum2 = 0, maxErr = 0;
	size_t worst = 0;
	for (size_t i = 0; i < count; i++) {
		const Eigen::Vector2d proj = (P * points[i].world.homogeneous()).hnormalized();
		const double err = (proj - points[i].image).norm();
		sum2 += err * err;
		if (!(err <= maxErr)) {
			maxErr = err;
			worst = i;
		}
	}
	out.projection = P;
	out.rmsError = std::sqrt(sum2 / static_cast<double>(count));
	out.maxError = maxErr;
	out.worstPoint = worst;
	return Status::success();
}

} // namespace

Status estimateProjectionDlt(const PointCorrespondence *points, size_t count, DltResult &out)
{
	return estimate(points, count, out);
}

} // namespace calped
