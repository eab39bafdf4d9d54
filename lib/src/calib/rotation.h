// SPDX-License-Identifier: BSD-2-Clause
// Rotation parameterisations found in calibration files, all giving world -> camera.
#pragma once

#include <Eigen/Core>

namespace calped::calib {

// Tsai's Euler angles: R = Rz(rz) Ry(ry) Rx(rx), radians.
Eigen::Matrix3d rotationFromTsaiEuler(double rx, double ry, double rz);
// Unit quaternion (x, y, z, w), Hamilton convention. The caller normalises.
Eigen::Matrix3d rotationFromQuaternion(double x, double y, double z, double w);
// Rodrigues vector (axis times angle in radians), as cv::Rodrigues.
Eigen::Matrix3d rotationFromRodrigues(const Eigen::Vector3d &r);
// R^T R = I and det R = +1 within `tolerance`.
bool isRotation(const Eigen::Matrix3d &R, double tolerance);

} // namespace calped::calib
