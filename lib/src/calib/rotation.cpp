// SPDX-License-Identifier: BSD-2-Clause
#include "calib/rotation.h"

#include <cmath>

#include <Eigen/Geometry>

namespace calped::calib {

Eigen::Matrix3d rotationFromTsaiEuler(double rx, double ry, double rz)
{
	const Eigen::Matrix3d Rx = Eigen::AngleAxisd(rx, Eigen::Vector3d::UnitX()).toRotationMatrix();
	const Eigen::Matrix3d Ry = Eigen::AngleAxisd(ry, Eigen::Vector3d::UnitY()).toRotationMatrix();
	const Eigen::Matrix3d Rz = Eigen::AngleAxisd(rz, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	return Rz * Ry * Rx;
}

Eigen::Matrix3d rotationFromQuaternion(double x, double y, double z, double w)
{
	return Eigen::Quaterniond(w, x, y, z).toRotationMatrix();
}

Eigen::Matrix3d rotationFromRodrigues(const Eigen::Vector3d &r)
{
	const double angle = r.norm();
	if (angle == 0.0)
		return Eigen::Matrix3d::Identity();
	return Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
}

bool isRotation(const Eigen::Matrix3d &R, double tolerance)
{
	if (!R.allFinite())
		return false;
	const double orth = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
	return orth <= tolerance && std::abs(R.determinant() - 1.0) <= tolerance;
}

} // namespace calped::calib
