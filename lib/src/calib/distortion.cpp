// SPDX-License-Identifier: BSD-2-Clause
// Lens distortion: Tsai's radial kappa1 and OpenCV's k1 k2 p1 p2 k3. Fixed-size types and
// bounded iterations only, so these may run per frame.
#include <calped/calibration.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace calped {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxIterations = 50;

// Tsai defines the distortion in the undistorting direction: ru = rd (1 + kappa1 rd^2).
// Solves it for rd with Newton's method: f(rd) = rd + k rd^3 - ru is increasing and convex
// for k > 0 (start right of the root at rd = ru); for k < 0 it is concave up to its maximum
// at rd = 1/sqrt(-3k) (start left of the root at 0). Both converge monotonically.
double tsaiDistortedRadius(double ru, double k)
{
	if (k == 0.0 || ru == 0.0)
		return ru;
	double rd = ru;
	if (k < 0.0) {
		const double turn = 1.0 / std::sqrt(-3.0 * k);
		if (ru > turn + k * turn * turn * turn)
			return kNaN;
		rd = 0.0;
	}
	for (int i = 0; i < kMaxIterations; i++) {
		const double f = rd + k * rd * rd * rd - ru;
		const double df = 1.0 + 3.0 * k * rd * rd;
		const double step = f / df;
		rd -= step;
		if (std::abs(step) <= 1e-12 * (1.0 + std::abs(rd)))
			break;
	}
	return rd;
}

// OpenCV's forward distortion of normalised coordinates, with its Jacobian.
Eigen::Vector2d openCvDistort(const OpenCvDistortion &d, const Eigen::Vector2d &p,
			      Eigen::Matrix2d *jacobian)
{
	const double x = p.x(), y = p.y();
	const double r2 = x * x + y * y;
	const double radial = 1.0 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
	const Eigen::Vector2d out(x * radial + 2.0 * d.p1 * x * y + d.p2 * (r2 + 2.0 * x * x),
				  y * radial + d.p1 * (r2 + 2.0 * y * y) + 2.0 * d.p2 * x * y);
	if (jacobian) {
		const double dRadial = d.k1 + r2 * (2.0 * d.k2 + 3.0 * d.k3 * r2); // d/d(r2)
		Eigen::Matrix2d &J = *jacobian;
		J(0, 0) = radial + 2.0 * x * x * dRadial + 2.0 * d.p1 * y + 6.0 * d.p2 * x;
		J(0, 1) = 2.0 * x * y * dRadial + 2.0 * d.p1 * x + 2.0 * d.p2 * y;
		J(1, 0) = J(0, 1);
		J(1, 1) = radial + 2.0 * y * y * dRadial + 6.0 * d.p1 * y + 2.0 * d.p2 * x;
	}
	return out;
}

} // namespace

Eigen::Vector2d CameraModel::undistort(const Eigen::Vector2d &pixel) const
{
	switch (distortionModel_) {
	case DistortionModel::None:
		return pixel;
	case DistortionModel::TsaiRadial: {
		// Pixel -> distorted sensor mm -> undistorted sensor mm: Xu = Xd (1 + k rd^2).
		const double xd = (pixel.x() - tsaiCx_) * tsaiMmPerPixelX_;
		const double yd = (pixel.y() - tsaiCy_) * tsaiMmPerPixelY_;
		const double f = 1.0 + kappa1_ * (xd * xd + yd * yd);
		return Eigen::Vector2d(tsaiCx_ + (pixel.x() - tsaiCx_) * f,
				       tsaiCy_ + (pixel.y() - tsaiCy_) * f);
	}
	case DistortionModel::OpenCv: {
		const Eigen::Vector2d target = (Kinv_ * pixel.homogeneous()).hnormalized();
		Eigen::Vector2d p = target;
		bool converged = false;
		for (int i = 0; i < kMaxIterations; i++) {
			Eigen::Matrix2d J;
			const Eigen::Vector2d r = openCvDistort(opencv_, p, &J) - target;
			const double det = J.determinant();
			if (!(std::abs(det) > 1e-12))
				break;
			const Eigen::Vector2d step = J.inverse() * r;
			p -= step;
			if (step.norm() <= 1e-12 * (1.0 + p.norm())) {
				converged = true;
				break;
			}
		}
		if (!converged || !p.allFinite())
			return Eigen::Vector2d(kNaN, kNaN);
		return (K_ * p.homogeneous()).head<2>();
	}
	}
	return pixel;
}

Eigen::Vector2d CameraModel::distort(const Eigen::Vector2d &point) const
{
	switch (distortionModel_) {
	case DistortionModel::None:
		return point;
	case DistortionModel::TsaiRadial: {
		const double xu = (point.x() - tsaiCx_) * tsaiMmPerPixelX_;
		const double yu = (point.y() - tsaiCy_) * tsaiMmPerPixelY_;
		const double ru = std::sqrt(xu * xu + yu * yu);
		if (ru == 0.0)
			return point;
		const double s = tsaiDistortedRadius(ru, kappa1_) / ru;
		return Eigen::Vector2d(tsaiCx_ + (point.x() - tsaiCx_) * s,
				       tsaiCy_ + (point.y() - tsaiCy_) * s);
	}
	case DistortionModel::OpenCv: {
		const Eigen::Vector2d p = (Kinv_ * point.homogeneous()).hnormalized();
		const Eigen::Vector2d d = openCvDistort(opencv_, p, nullptr);
		return (K_ * d.homogeneous()).head<2>();
	}
	}
	return point;
}

} // namespace calped
