// SPDX-License-Identifier: BSD-2-Clause
// Building a CameraModel: validation, conversion to metres and the derived matrices.
#include <calped/calibration.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include "calib/rotation.h"

namespace calped {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Singular values below this fraction of the largest make P's left block singular.
constexpr double kRankTolerance = 1e-10;

Status checkIntrinsics(const Eigen::Matrix3d &K)
{
	if (!K.allFinite())
		return Status::error(ErrorCode::InvalidArgument, "camera matrix K is not finite");
	if (K(1, 0) != 0.0 || K(2, 0) != 0.0 || K(2, 1) != 0.0)
		return Status::error(ErrorCode::InvalidArgument,
				     "camera matrix K is not upper triangular");
	if (std::abs(K(2, 2) - 1.0) > 1e-12)
		return Status::error(ErrorCode::InvalidArgument,
				     "camera matrix K(2,2) is %g, expected 1", K(2, 2));
	if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
		return Status::error(ErrorCode::InvalidArgument,
				     "camera matrix focal lengths fx = %g, fy = %g must be > 0",
				     K(0, 0), K(1, 1));
	return Status::success();
}

Status checkExtrinsics(const Eigen::Matrix3d &R, const Eigen::Vector3d &t)
{
	if (!calib::isRotation(R, 1e-6))
		return Status::error(ErrorCode::InvalidArgument,
				     "R is not a rotation matrix (R^T R != I or det R != 1)");
	if (!t.allFinite())
		return Status::error(ErrorCode::InvalidArgument, "translation is not finite");
	return Status::success();
}

} // namespace

CameraModel::CameraModel()
{
	P_.setConstant(kNaN);
	H_.setConstant(kNaN);
	Hinv_.setConstant(kNaN);
	centre_.setConstant(kNaN);
	K_.setConstant(kNaN);
	Kinv_.setConstant(kNaN);
	R_.setConstant(kNaN);
	t_.setConstant(kNaN);
}

// Converts P to metres, normalises its scale and sign, and derives H, H^-1 and the centre.
Status CameraModel::finish(const Matrix34d &Pin, LengthUnit unit)
{
	valid_ = false;
	if (!Pin.allFinite())
		return Status::error(ErrorCode::InvalidArgument, "projection matrix is not finite");

	// X_unit = X_metres / metresPerUnit: the first three columns absorb the factor.
	Matrix34d P = Pin;
	P.leftCols<3>() /= metresPerUnit(unit);

	const Eigen::Matrix3d M = P.leftCols<3>();
	Eigen::JacobiSVD<Eigen::Matrix3d> svd(M);
	const Eigen::Vector3d sv = svd.singularValues();
	if (!(sv(0) > 0.0) || sv(2) < kRankTolerance * sv(0))
		return Status::error(ErrorCode::InvalidArgument,
				     "projection matrix is degenerate: its left 3x3 block is "
				     "singular (singular values %.3g %.3g %.3g)",
				     sv(0), sv(1), sv(2));

	// Third row of M = depth direction: unit length, and det M > 0 so that depth is
	// positive in front of the camera (Hartley & Zisserman 6.2.3).
	double scale = 1.0 / M.row(2).norm();
	if (M.determinant() < 0.0)
		scale = -scale;
	P *= scale;

	const Eigen::Vector3d C = -P.leftCols<3>().inverse() * P.col(3);
	if (!C.allFinite())
		return Status::error(ErrorCode::InvalidArgument,
				     "projection matrix is degenerate: no finite camera centre");
	if (!(C.z() > 0.0))
		return Status::error(ErrorCode::InvalidArgument,
				     "camera centre (%.4g, %.4g, %.4g) m is not above the ground "
				     "plane z = 0 (the world z axis must point up)",
				     C.x(), C.y(), C.z());

	Eigen::Matrix3d H;
	H.col(0) = P.col(0);
	H.col(1) = P.col(1);
	H.col(2) = P.col(3);
	// det H is proportional to the centre's height; checked above, so H is invertible.
	const Eigen::Matrix3d Hinv = H.inverse();
	if (!Hinv.allFinite())
		return Status::error(ErrorCode::InvalidArgument,
				     "ground-plane homography is not invertible");

	P_ = P;
	H_ = H;
	Hinv_ = Hinv;
	centre_ = C;
	sourceUnit_ = unit;
	valid_ = true;
	return Status::success();
}

Status CameraModel::fromProjection(const Matrix34d &P, LengthUnit unit, CameraModel &out)
{
	CameraModel m;
	Status st = m.finish(P, unit);
	if (!st.ok())
		return st;
	out = m;
	return st;
}

Status CameraModel::fromPinhole(const Eigen::Matrix3d &K, const Eigen::Matrix3d &R,
				const Eigen::Vector3d &t, LengthUnit unit, CameraModel &out)
{
	return fromOpenCv(K, R, t, OpenCvDistortion(), unit, out);
}

Status CameraModel::fromOpenCv(const Eigen::Matrix3d &K, const Eigen::Matrix3d &R,
			       const Eigen::Vector3d &t, const OpenCvDistortion &distortion,
			       LengthUnit unit, CameraModel &out)
{
	Status st = checkIntrinsics(K);
	if (!st.ok())
		return st;
	st = checkExtrinsics(R, t);
	if (!st.ok())
		return st;
	const double d[] = { distortion.k1, distortion.k2, distortion.p1, distortion.p2,
			     distortion.k3 };
	for (double v : d)
		if (!std::isfinite(v))
			return Status::error(ErrorCode::InvalidArgument,
					     "distortion coefficients are not finite");

	CameraModel m;
	const Eigen::Vector3d tm = t * metresPerUnit(unit);
	Matrix34d P;
	P.leftCols<3>() = K * R;
	P.col(3) = K * tm;
	st = m.finish(P, LengthUnit::Metre);
	if (!st.ok())
		return st;
	m.sourceUnit_ = unit;
	m.hasPinhole_ = true;
	m.K_ = K;
	m.Kinv_ = K.inverse();
	m.R_ = R;
	m.t_ = tm;
	const bool distorted = d[0] != 0.0 || d[1] != 0.0 || d[2] != 0.0 || d[3] != 0.0 ||
			       d[4] != 0.0;
	m.distortionModel_ = distorted ? DistortionModel::OpenCv : DistortionModel::None;
	m.opencv_ = distortion;
	out = m;
	return st;
}

Status CameraModel::checkFrameSize(int width, int height) const
{
	if (width_ > 0 && (width_ != width || height_ != height))
		return Status::error(ErrorCode::InvalidArgument,
				     "the calibration is for %dx%d images, the frames are %dx%d", width_,
				     height_, width, height);
	// Cameras put the principal point near the image centre; one outside the frame means
	// the calibration's pixels are not these frames' (another resolution or a crop).
	if (hasPinhole_) {
		const double cx = K_(0, 2), cy = K_(1, 2);
		if (!(cx >= 0.0 && cx <= width && cy >= 0.0 && cy <= height))
			return Status::error(ErrorCode::InvalidArgument,
					     "the calibration's principal point (%.1f, %.1f) is outside the "
					     "%dx%d frames: it is for frames of another size (about %.0fx%.0f?)",
					     cx, cy, width, height, 2.0 * cx + 1.0, 2.0 * cy + 1.0);
	}
	return Status::success();
}

Status CameraModel::fromTsai(const TsaiCamera &c, LengthUnit unit, CameraModel &out)
{
	struct Field {
		const char *name;
		double value;
		bool positive;
	};
	const Field fields[] = {
		{ "width", c.width, true }, { "height", c.height, true },
		{ "ncx", c.ncx, true },	    { "nfx", c.nfx, true },
		{ "dx", c.dx, true },	    { "dy", c.dy, true },
		{ "dpx", c.dpx, true },	    { "dpy", c.dpy, true },
		{ "focal", c.focal, true }, { "kappa1", c.kappa1, false },
		{ "cx", c.cx, false },	    { "cy", c.cy, false },
		{ "sx", c.sx, true },	    { "tx", c.tx, false },
		{ "ty", c.ty, false },	    { "tz", c.tz, false },
		{ "rx", c.rx, false },	    { "ry", c.ry, false },
		{ "rz", c.rz, false },
	};
	for (const Field &f : fields) {
		if (!std::isfinite(f.value))
			return Status::error(ErrorCode::InvalidArgument,
					     "Tsai parameter %s is not finite", f.name);
		if (f.positive && !(f.value > 0.0))
			return Status::error(ErrorCode::InvalidArgument,
					     "Tsai parameter %s = %g must be > 0", f.name, f.value);
	}
	if (c.width != std::floor(c.width) || c.height != std::floor(c.height) ||
	    c.width > 1 << 20 || c.height > 1 << 20)
		return Status::error(ErrorCode::InvalidArgument,
				     "Tsai image size %g x %g is not a plausible pixel count",
				     c.width, c.height);

	// Undistorted sensor mm -> pixels on the image's own grid.
	Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
	K(0, 0) = c.sx * c.focal / c.dpx;
	K(1, 1) = c.focal / c.dpy;
	K(0, 2) = c.cx;
	K(1, 2) = c.cy;
	const Eigen::Matrix3d R = calib::rotationFromTsaiEuler(c.rx, c.ry, c.rz);
	const Eigen::Vector3d t(c.tx, c.ty, c.tz);

	CameraModel m;
	Status st = fromPinhole(K, R, t, unit, m);
	if (!st.ok())
		return st;
	m.width_ = static_cast<int>(c.width);
	m.height_ = static_cast<int>(c.height);
	m.distortionModel_ = c.kappa1 != 0.0 ? DistortionModel::TsaiRadial : DistortionModel::None;
	m.kappa1_ = c.kappa1;
	m.tsaiMmPerPixelX_ = c.dpx / c.sx;
	m.tsaiMmPerPixelY_ = c.dpy;
	m.tsaiCx_ = c.cx;
	m.tsaiCy_ = c.cy;
	out = m;
	return st;
}

} // namespace calped
