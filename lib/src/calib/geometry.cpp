// SPDX-License-Identifier: BSD-2-Clause
// Ground-plane geometry of a calibrated camera (thesis eqs. 2.3-2.8). Fixed-size types
// only: nothing here allocates.
#include <calped/calibration.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace calped {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
} // namespace

Eigen::Vector2d CameraModel::project(const Eigen::Vector3d &world) const
{
	const Eigen::Vector3d x = P_ * world.homogeneous();
	return x.hnormalized();
}

double CameraModel::depth(const Eigen::Vector3d &world) const
{
	return P_.row(2).dot(world.homogeneous());
}

Eigen::Vector3d CameraModel::horizon() const
{
	// Third row of H^-1: its value at an image point is 1 / depth of the ground point seen
	// there, so it vanishes on the horizon and is positive below it.
	return Hinv_.row(2).transpose();
}

double CameraModel::horizonRow(double u) const
{
	const Eigen::Vector3d l = horizon();
	if (l.y() == 0.0)
		return kNaN;
	return -(l.x() * u + l.z()) / l.y();
}

bool CameraModel::groundPoint(const Eigen::Vector2d &point, Eigen::Vector2d &ground) const
{
	const Eigen::Vector3d g = Hinv_ * point.homogeneous();
	if (!(g.z() > 0.0))
		return false;
	const Eigen::Vector2d xy = g.hnormalized();
	if (!xy.allFinite())
		return false;
	ground = xy;
	return true;
}

double CameraModel::worldHeight(const Eigen::Vector2d &foot, const Eigen::Vector2d &head) const
{
	// Eq. 2.8: with g = H^-1 (u, vb, 1), the head (g.x, g.y, h g.z, g.z) projects to
	// (u, vb, 1) + h g.z p3; equating its row to vt gives h.
	const double w = Hinv_.row(2).dot(foot.homogeneous());
	if (!(w > 0.0))
		return kNaN;
	const double denom = w * (P_(1, 2) - head.y() * P_(2, 2));
	const double h = (head.y() - foot.y()) / denom;
	return std::isfinite(h) ? h : kNaN;
}

bool CameraModel::headPoint(const Eigen::Vector2d &foot, double height,
			    Eigen::Vector2d &head) const
{
	const double w = Hinv_.row(2).dot(foot.homogeneous());
	if (!(w > 0.0) || !std::isfinite(height))
		return false;
	const Eigen::Vector3d q = foot.homogeneous() + (height * w) * P_.col(2);
	// q.z() is the head's depth over the foot's.
	if (!(q.z() > 0.0))
		return false;
	head = q.hnormalized();
	return head.allFinite();
}

double CameraModel::pixelHeight(const Eigen::Vector2d &foot, double height) const
{
	Eigen::Vector2d head;
	if (!headPoint(foot, height, head))
		return kNaN;
	return foot.y() - head.y();
}

Eigen::Vector2d CameraModel::worldToPixel(const Eigen::Vector3d &world) const
{
	return distort(project(world));
}

bool CameraModel::pixelToGround(const Eigen::Vector2d &pixel, Eigen::Vector2d &ground) const
{
	const Eigen::Vector2d p = undistort(pixel);
	if (!p.allFinite())
		return false;
	return groundPoint(p, ground);
}

double CameraModel::boxWorldHeight(const Eigen::Vector2d &footPixel,
				   const Eigen::Vector2d &headPixel) const
{
	return worldHeight(undistort(footPixel), undistort(headPixel));
}

double CameraModel::boxPixelHeight(const Eigen::Vector2d &footPixel, double height) const
{
	Eigen::Vector2d head;
	if (!headPoint(undistort(footPixel), height, head))
		return kNaN;
	double r1 = distort(head).y();
	if (distortionModel_ == DistortionModel::None || !std::isfinite(r1))
		return footPixel.y() - r1;

	// Distortion moves the true head off the foot's column, but a box's head is on it:
	// refine the row (secant steps) so that boxWorldHeight() of the box gives `height`
	// back, making the two functions exact inverses for axis-aligned boxes.
	auto residual = [&](double row) {
		return boxWorldHeight(footPixel, Eigen::Vector2d(footPixel.x(), row)) - height;
	};
	double r0 = r1 + 1.0;
	double f0 = residual(r0), f1 = residual(r1);
	for (int i = 0; i < 20 && std::isfinite(f0) && std::isfinite(f1) && f1 != f0; i++) {
		const double r2 = r1 - f1 * (r1 - r0) / (f1 - f0);
		r0 = r1;
		f0 = f1;
		r1 = r2;
		f1 = residual(r1);
		if (std::abs(r1 - r0) < 1e-10)
			break;
	}
	return std::isfinite(f1) ? footPixel.y() - r1 : kNaN;
}

} // namespace calped
