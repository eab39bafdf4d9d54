// SPDX-License-Identifier: BSD-2-Clause
// Oxford Town Centre calibration (".ci" text): one "Key = value" per line; intrinsics in
// pixels, world -> camera rotation as a unit quaternion, translation in metres, OpenCV
// distortion k1 k2 p1 p2.
#include <calped/calibration.h>

#include <cmath>
#include <string_view>

#include "calib/rotation.h"
#include "calib/text_util.h"

namespace calped {

namespace {

enum Key {
	FocalLengthX, FocalLengthY, PrincipalPointX, PrincipalPointY, Skew,
	TranslationX, TranslationY, TranslationZ,
	RotationX, RotationY, RotationZ, RotationW,
	DistortionK1, DistortionK2, DistortionP1, DistortionP2,
	KeyCount
};

const char *const kKeyNames[KeyCount] = {
	"FocalLengthX", "FocalLengthY", "PrincipalPointX", "PrincipalPointY", "Skew",
	"TranslationX", "TranslationY", "TranslationZ",
	"RotationX", "RotationY", "RotationZ", "RotationW",
	"DistortionK1", "DistortionK2", "DistortionP1", "DistortionP2",
};

} // namespace

Status loadTownCentreCi(const char *data, size_t size, const char *name, CameraModel &out)
{
	using calib::fileError;
	double v[KeyCount] = {};
	int lineOf[KeyCount] = {};

	calib::LineReader lines(data, size);
	std::string_view line;
	while (lines.next(line)) {
		const int n = lines.lineNumber();
		const std::string_view text = calib::trim(calib::stripComment(line));
		if (text.empty())
			continue;
		const size_t eq = text.find('=');
		char q[48];
		if (eq == std::string_view::npos)
			return fileError(ErrorCode::ParseError, name, n,
					 "expected 'Key = value', found '%s'",
					 calib::quote(text, q, sizeof(q)));
		const std::string_view key = calib::trim(text.substr(0, eq));
		const std::string_view value = calib::trim(text.substr(eq + 1));
		int k = 0;
		while (k < KeyCount && key != kKeyNames[k])
			k++;
		if (k == KeyCount)
			return fileError(ErrorCode::ParseError, name, n, "unknown key '%s'",
					 calib::quote(key, q, sizeof(q)));
		if (lineOf[k])
			return fileError(ErrorCode::ParseError, name, n,
					 "%s given twice (first on line %d)", kKeyNames[k], lineOf[k]);
		const calib::NumberResult r = calib::parseNumber(value, v[k]);
		if (r != calib::NumberResult::Ok)
			return calib::numberError(r, name, n, kKeyNames[k], value);
		lineOf[k] = n;
	}
	for (int k = 0; k < KeyCount; k++)
		if (!lineOf[k])
			return fileError(ErrorCode::ParseError, name, 0, "missing key %s",
					 kKeyNames[k]);

	const double qn = std::sqrt(v[RotationX] * v[RotationX] + v[RotationY] * v[RotationY] +
				    v[RotationZ] * v[RotationZ] + v[RotationW] * v[RotationW]);
	// A file rounds its quaternion; a grossly non-unit one is a wrong file, not rounding.
	if (std::abs(qn - 1.0) > 1e-3)
		return fileError(ErrorCode::InvalidArgument, name, lineOf[RotationX],
				 "rotation quaternion has norm %.6g, expected 1", qn);

	Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
	K(0, 0) = v[FocalLengthX];
	K(1, 1) = v[FocalLengthY];
	K(0, 1) = v[Skew];
	K(0, 2) = v[PrincipalPointX];
	K(1, 2) = v[PrincipalPointY];
	if (!(K(0, 0) > 0.0) || !(K(1, 1) > 0.0))
		return fileError(ErrorCode::InvalidArgument, name,
				 lineOf[K(0, 0) > 0.0 ? FocalLengthY : FocalLengthX],
				 "focal lengths %g, %g must be > 0", K(0, 0), K(1, 1));
	const Eigen::Matrix3d R = calib::rotationFromQuaternion(
		v[RotationX] / qn, v[RotationY] / qn, v[RotationZ] / qn, v[RotationW] / qn);
	const Eigen::Vector3d t(v[TranslationX], v[TranslationY], v[TranslationZ]);
	OpenCvDistortion d;
	d.k1 = v[DistortionK1];
	d.k2 = v[DistortionK2];
	d.p1 = v[DistortionP1];
	d.p2 = v[DistortionP2];
	return calib::withFileName(CameraModel::fromOpenCv(K, R, t, d, LengthUnit::Metre, out),
				   name);
}

} // namespace calped
