// SPDX-License-Identifier: BSD-2-Clause
// Calibrated cameras: the projection matrix, the ground-plane homography, lens distortion,
// world heights of image boxes, calibration file loaders and the direct linear transform.
// Conventions (docs/calibration.md): world z points up, the ground is the plane z = 0,
// world lengths are metres; image u points right, v down, in pixels.
#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

#include <calped/status.h>

namespace calped {

using Matrix34d = Eigen::Matrix<double, 3, 4>;

// Length unit of a calibration file's world coordinates. Models always store metres.
enum class LengthUnit { Millimetre, Centimetre, Metre };

// "mm", "cm" or "m".
const char *lengthUnitName(LengthUnit unit);
// 0.001, 0.01 or 1.
double metresPerUnit(LengthUnit unit);
// Parses exactly "mm", "cm" or "m"; false for anything else.
bool parseLengthUnit(const char *text, size_t length, LengthUnit &out);

enum class DistortionModel {
	None,       // pinhole: pixels are used as they are
	TsaiRadial, // Tsai's single radial term kappa1 in sensor millimetres
	OpenCv,     // OpenCV's k1 k2 p1 p2 k3 on normalised coordinates
};

// Tsai's camera as Willson's calibration code and PETS 2009 write it. Sensor values are in
// millimetres on the sensor; the translation is in the file's world unit.
struct TsaiCamera {
	// Geometry: image size, sensor elements (ncx) and frame-grabber pixels (nfx) per row,
	// sensor element size (dx, dy) and effective pixel size (dpx, dpy), mm.
	double width = 0, height = 0, ncx = 0, nfx = 0, dx = 0, dy = 0, dpx = 0, dpy = 0;
	// Intrinsic: focal length (mm), radial distortion (1/mm^2), distortion centre
	// (pixels), horizontal scale factor.
	double focal = 0, kappa1 = 0, cx = 0, cy = 0, sx = 1;
	// Extrinsic: translation and Euler angles (radians), X_camera = R X_world + T with
	// R = Rz(rz) Ry(ry) Rx(rx).
	double tx = 0, ty = 0, tz = 0, rx = 0, ry = 0, rz = 0;
};

// OpenCV's distortion coefficients (k3 = 0 when the calibration has only four).
struct OpenCvDistortion {
	double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
};

// A calibrated camera. It holds the projection matrix P (world metres to undistorted image
// points) and, when the calibration has them, the intrinsics K, the extrinsics R, t and the
// lens distortion. "Pixels" are image coordinates as captured; "points" are undistorted image
// coordinates, those P maps to. Without distortion the two are the same.
//
// The geometry functions use fixed-size Eigen types only: they never allocate, so the
// detector may call them per frame. On an invalid (default-constructed) model, or where a
// result does not exist (a point above the horizon, a head behind the camera), they return
// NaN or false as documented.
class CameraModel
{
public:
	CameraModel();

	// P maps homogeneous world coordinates in `unit` to homogeneous undistorted image points.
	// Fails with InvalidArgument when P is not finite, its left 3x3 block is singular, or the
	// camera centre is not above the ground plane (z > 0).
	static Status fromProjection(const Matrix34d &P, LengthUnit unit, CameraModel &out);
	// Pinhole camera: X_camera = R X_world + t (t in `unit`), point = K X_camera. K must be
	// upper triangular with positive focal lengths and K(2,2) = 1; R a rotation.
	static Status fromPinhole(const Eigen::Matrix3d &K, const Eigen::Matrix3d &R,
				  const Eigen::Vector3d &t, LengthUnit unit, CameraModel &out);
	// The same plus OpenCV's distortion.
	static Status fromOpenCv(const Eigen::Matrix3d &K, const Eigen::Matrix3d &R,
				 const Eigen::Vector3d &t, const OpenCvDistortion &distortion,
				 LengthUnit unit, CameraModel &out);
	// Tsai's model. Undistorted points use the same pixel grid as the image:
	// u = sx Xu / dpx + cx, v = Yu / dpy + cy for undistorted sensor coordinates (Xu, Yu).
	static Status fromTsai(const TsaiCamera &camera, LengthUnit unit, CameraModel &out);

	bool valid() const { return valid_; }

	// Projection matrix for world metres, scaled so that its third row gives a point's depth
	// along the optical axis in metres (positive in front of the camera).
	const Matrix34d &projection() const { return P_; }
	// Ground-plane homography H = [p1 p2 p4] (eq. 2.6): ground (x, y, 1) -> image point.
	const Eigen::Matrix3d &homography() const { return H_; }
	// H^-1 (eq. 2.7): image point -> ground.
	const Eigen::Matrix3d &inverseHomography() const { return Hinv_; }
	// Camera centre in world metres.
	const Eigen::Vector3d &centre() const { return centre_; }

	// Intrinsics and extrinsics (metres) when the calibration has them (not for a bare P).
	bool hasPinhole() const { return hasPinhole_; }
	const Eigen::Matrix3d &intrinsics() const { return K_; }
	const Eigen::Matrix3d &rotation() const { return R_; }
	const Eigen::Vector3d &translation() const { return t_; }

	DistortionModel distortionModel() const { return distortionModel_; }
	const OpenCvDistortion &openCvDistortion() const { return opencv_; }
	double tsaiKappa1() const { return kappa1_; }

	// Image size when the calibration states it (Tsai), else 0.
	int imageWidth() const { return width_; }
	int imageHeight() const { return height_; }
	// Whether this calibration can be for width x height frames: InvalidArgument naming
	// both sizes when it states another image size (Tsai), or when its principal point (a
	// calibration with intrinsics) lies outside such a frame, as a 1920x1080 camera's
	// (959.5, 539.5) does on 768x576 frames: a calibration made for frames of another size
	// finds nobody, silently. The one check of the detector (DetectorConfig::validate), the
	// programs and the GStreamer element.
	Status checkFrameSize(int width, int height) const;
	// Unit of the source calibration (informative; the model itself is in metres).
	LengthUnit sourceUnit() const { return sourceUnit_; }

	// Captured pixel -> undistorted point (exact for Tsai, Newton iterations for OpenCV).
	// NaN when the iteration does not converge. The identity without distortion.
	Eigen::Vector2d undistort(const Eigen::Vector2d &pixel) const;
	// Undistorted point -> captured pixel. NaN where no pixel maps there (Tsai kappa1 < 0
	// beyond the turning radius).
	Eigen::Vector2d distort(const Eigen::Vector2d &point) const;

	// --- Geometry on undistorted points ---

	// World point (metres) -> undistorted image point (eqs. 2.3-2.4).
	Eigen::Vector2d project(const Eigen::Vector3d &world) const;
	// Depth of a world point along the optical axis, metres (<= 0: behind the camera).
	double depth(const Eigen::Vector3d &world) const;
	// Horizon: the image line (a, b, c), a u + b v + c = 0, where the ground plane vanishes;
	// a u + b v + c > 0 for points that see the ground in front of the camera.
	Eigen::Vector3d horizon() const;
	// Row of the horizon at column u (NaN when the horizon is vertical).
	double horizonRow(double u) const;
	// Image point -> ground point (x, y) in metres (eq. 2.7). False, ground untouched, when
	// the point is on or above the horizon.
	bool groundPoint(const Eigen::Vector2d &point, Eigen::Vector2d &ground) const;
	// World height (metres) of a standing person whose feet are at image point `foot` and
	// whose head is on row head.y() (eq. 2.8: the height h such that the ground point under
	// the foot, raised by h, projects to the head's row; the head's column is not used, as
	// boxes are axis-aligned). NaN when the foot is on or above the horizon.
	double worldHeight(const Eigen::Vector2d &foot, const Eigen::Vector2d &head) const;
	// Image point of the head of a person of world height `height` (metres) standing at
	// `foot`. False when the foot is on or above the horizon or the head is behind the camera.
	bool headPoint(const Eigen::Vector2d &foot, double height, Eigen::Vector2d &head) const;
	// Pixel height (foot.y() - head row) of a person of world height `height` standing at
	// `foot`; the reverse of worldHeight(). NaN where headPoint() fails.
	double pixelHeight(const Eigen::Vector2d &foot, double height) const;

	// --- The same on captured pixels (distortion applied or removed) ---

	// World point -> captured pixel.
	Eigen::Vector2d worldToPixel(const Eigen::Vector3d &world) const;
	// Captured pixel -> ground point.
	bool pixelToGround(const Eigen::Vector2d &pixel, Eigen::Vector2d &ground) const;
	// World height of a box given its foot (bottom centre) and head (top centre) pixels.
	double boxWorldHeight(const Eigen::Vector2d &footPixel,
			      const Eigen::Vector2d &headPixel) const;
	// Pixel height of an axis-aligned box of world height `height` whose foot is at pixel
	// `footPixel`: the inverse of boxWorldHeight() (with distortion the head row is refined
	// so that boxWorldHeight(foot, (foot.x, foot.y - result)) == height).
	double boxPixelHeight(const Eigen::Vector2d &footPixel, double height) const;

private:
	Status finish(const Matrix34d &P, LengthUnit unit);

	bool valid_ = false;
	Matrix34d P_;
	Eigen::Matrix3d H_, Hinv_;
	Eigen::Vector3d centre_;

	bool hasPinhole_ = false;
	Eigen::Matrix3d K_, Kinv_, R_;
	Eigen::Vector3d t_;

	DistortionModel distortionModel_ = DistortionModel::None;
	OpenCvDistortion opencv_;
	// Tsai: pixel -> sensor mm factors and distortion centre.
	double kappa1_ = 0, tsaiMmPerPixelX_ = 0, tsaiMmPerPixelY_ = 0, tsaiCx_ = 0, tsaiCy_ = 0;

	int width_ = 0, height_ = 0;
	LengthUnit sourceUnit_ = LengthUnit::Metre;
};

// --- Calibration files (docs/calibration.md). The core reads memory buffers; `name` is the
// file name used in error messages. Malformed input gives ParseError (naming the line),
// values out of range InvalidArgument (naming the field). ---

// Tsai XML as PETS 2009 ships it (millimetres).
Status loadTsaiXml(const char *data, size_t size, const char *name, CameraModel &out);
// The same, keeping the parsed parameters (for tools and tests).
Status parseTsaiXml(const char *data, size_t size, const char *name, TsaiCamera &out);
// Oxford Town Centre ".ci" text: "Key = value" lines (metres).
Status loadTownCentreCi(const char *data, size_t size, const char *name, CameraModel &out);
// Plain projection matrix: 3 rows of 4 numbers, '#' comments, optional "unit: mm|cm|m".
Status loadProjectionText(const char *data, size_t size, const char *name, CameraModel &out);
// OpenCV FileStorage YAML (camera_matrix, distortion_coefficients, rvec/tvec or R/t, unit).
Status loadOpenCvYaml(const char *data, size_t size, const char *name, CameraModel &out);

enum class CalibrationFormat { Unknown, TsaiXml, TownCentreCi, ProjectionText, OpenCvYaml };
const char *calibrationFormatName(CalibrationFormat format);
// Guesses the format from the content: "%YAML" -> OpenCV, '<' -> Tsai XML, "Key = value"
// -> Town Centre, otherwise a projection matrix. Unknown only for empty input.
CalibrationFormat detectCalibrationFormat(const char *data, size_t size);
// Detects the format and loads it.
Status loadCalibration(const char *data, size_t size, const char *name, CameraModel &out);

// The plain projection-matrix text for P (world in `unit`), loadable by loadProjectionText().
// `comment` (may be empty) is written as '#' lines at the top. Numbers keep full precision.
Status formatProjectionText(const Matrix34d &P, LengthUnit unit, const std::string &comment,
			    std::string &out);

// --- Direct linear transform (thesis chapter 2.3) ---

struct PointCorrespondence {
	Eigen::Vector2d image; // pixels (undistorted)
	Eigen::Vector3d world; // any unit; P comes out in the same unit
};

struct DltResult {
	// Scaled so that its third row gives depth (positive in front of the camera).
	Matrix34d projection = Matrix34d::Zero();
	double rmsError = 0; // reprojection error over all points, pixels
	double maxError = 0;
	size_t worstPoint = 0; // index of the point with maxError
};

// Estimates P from >= 6 correspondences with Hartley normalisation of both point sets and
// an SVD. InvalidArgument for fewer than 6 points, non-finite values, coincident or coplanar
// world points, or any other rank-deficient configuration. Does not allocate.
Status estimateProjectionDlt(const PointCorrespondence *points, size_t count, DltResult &out);

} // namespace calped
