// SPDX-License-Identifier: BSD-2-Clause
// The self-calibrated camera (f, tilt, roll, height), the same parameters read back from any
// CameraModel, and the OpenCV YAML that loadOpenCvYaml() reads.
#include <calped/self_calibration.h>

#include <cmath>
#include <cstdio>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "selfcal/fit.h"

namespace calped {

Eigen::Matrix3d selfCalibrationRotation(double tilt, double roll)
{
	// Rows are the camera axes in world coordinates. Level: x right = world x, y down =
	// -world z, z forward = world y; tilting down turns forward towards -z; roll turns the
	// image about the optical axis.
	const double st = std::sin(tilt), ct = std::cos(tilt);
	const Eigen::Vector3d x(1, 0, 0), y(0, -st, -ct), z(0, ct, -st);
	const double sr = std::sin(roll), cr = std::cos(roll);
	Eigen::Matrix3d R;
	R.row(0) = (cr * x - sr * y).transpose();
	R.row(1) = (sr * x + cr * y).transpose();
	R.row(2) = z.transpose();
	return R;
}

Status makeSelfCalibratedCamera(double focal, double tilt, double roll, double height, double cu,
				double cv, CameraModel &out)
{
	if (!(focal > 0) || !(height > 0) || !(std::abs(tilt) < M_PI / 2) || !std::isfinite(roll) ||
	    !std::isfinite(cu) || !std::isfinite(cv))
		return Status::error(ErrorCode::InvalidArgument,
				     "self-calibrated camera: focal %g px, height %g m, tilt %g rad "
				     "(needs focal > 0, height > 0, |tilt| < pi/2)", focal, height, tilt);
	Eigen::Matrix3d K;
	K << focal, 0, cu, 0, focal, cv, 0, 0, 1;
	const Eigen::Matrix3d R = selfCalibrationRotation(tilt, roll);
	const Eigen::Vector3d t = -R * Eigen::Vector3d(0, 0, height);
	return CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, out);
}

bool cameraParameters(const CameraModel &camera, double u, CameraParameters &out)
{
	if (!camera.valid())
		return false;
	Eigen::Matrix3d K, R;
	if (camera.hasPinhole()) {
		K = camera.intrinsics();
		R = camera.rotation();
	} else {
		// P's left block M = K R with R's third row a unit vector (P is depth-scaled):
		// M M^T = K K^T gives K, then R = K^-1 M.
		const Eigen::Matrix3d M = camera.projection().leftCols<3>();
		const Eigen::Matrix3d A = M * M.transpose();
		const double cx = A(0, 2), cy = A(1, 2);
		const double fy = std::sqrt(std::max(A(1, 1) - cy * cy, 0.0));
		const double s = fy > 0 ? (A(0, 1) - cx * cy) / fy : 0;
		const double fx = std::sqrt(std::max(A(0, 0) - s * s - cx * cx, 0.0));
		K << fx, s, cx, 0, fy, cy, 0, 0, 1;
		R = K.inverse() * M;
	}
	out.focal = K(1, 1);
	out.tilt = std::asin(std::clamp(-R(2, 2), -1.0, 1.0));
	out.roll = std::atan2(R(0, 2), -R(1, 2));
	out.height = camera.centre().z();
	out.horizonRow = camera.horizonRow(u);
	return true;
}

namespace {

void appendMatrix(std::string &out, const char *key, const double *values, int rows, int cols)
{
	char line[128];
	std::snprintf(line, sizeof(line), "%s: !!opencv-matrix\n   rows: %d\n   cols: %d\n   dt: d\n   data: [",
		      key, rows, cols);
	out += line;
	for (int i = 0; i < rows * cols; i++) {
		std::snprintf(line, sizeof(line), "%s %.17g", i ? "," : "", values[i]);
		out += line;
	}
	out += " ]\n";
}

} // namespace

Status formatOpenCvYaml(const CameraModel &camera, const std::string &comment, std::string &out)
{
	if (!camera.valid() || !camera.hasPinhole() || camera.distortionModel() != DistortionModel::None)
		return Status::error(ErrorCode::InvalidArgument,
				     "formatOpenCvYaml needs a valid pinhole camera without distortion");
	out = "%YAML:1.0\n---\n";
	size_t start = 0;
	while (start < comment.size()) {
		size_t end = comment.find('\n', start);
		if (end == std::string::npos)
			end = comment.size();
		out += "# " + comment.substr(start, end - start) + "\n";
		start = end + 1;
	}
	double k[9], r[9], t[3];
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++) {
			k[3 * i + j] = camera.intrinsics()(i, j);
			r[3 * i + j] = camera.rotation()(i, j);
		}
		t[i] = camera.translation()(i);
	}
	appendMatrix(out, "camera_matrix", k, 3, 3);
	const double distortion[5] = { 0, 0, 0, 0, 0 };
	appendMatrix(out, "distortion_coefficients", distortion, 1, 5);
	appendMatrix(out, "R", r, 3, 3);
	appendMatrix(out, "t", t, 3, 1);
	out += "unit: m\n";
	return Status::success();
}

} // namespace calped
