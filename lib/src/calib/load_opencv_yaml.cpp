// SPDX-License-Identifier: BSD-2-Clause
// OpenCV FileStorage YAML as cv::calibrateCamera / cv::solvePnP users keep it: camera
// matrix, distortion coefficients, the pose as rvec/tvec or R/t, and a "unit" key (ours)
// naming the unit of the translation.
#include <calped/calibration.h>

#include <new>
#include <string>

#include "calib/rotation.h"
#include "calib/text_util.h"
#include "calib/yaml_reader.h"

namespace calped {

namespace {

using calib::fileError;
using calib::YamlDocument;
using calib::YamlEntry;

// The first of `keys` present in the document, or null.
const YamlEntry *findAny(const YamlDocument &doc, std::initializer_list<const char *> keys)
{
	for (const char *k : keys)
		if (const YamlEntry *e = doc.find(k))
			return e;
	return nullptr;
}

// A matrix of exactly rows x cols (a vector may be written as a row or a column).
Status readMatrix(const YamlDocument &doc, const YamlEntry &e, int rows, int cols, double *out)
{
	YamlDocument::Matrix m;
	Status st = doc.matrix(e, m);
	if (!st.ok())
		return st;
	const bool vector = rows == 1 || cols == 1;
	const bool shapeOk = vector ? (m.rows == 1 || m.cols == 1) && m.rows * m.cols == rows * cols
				    : m.rows == rows && m.cols == cols;
	if (!shapeOk)
		return fileError(ErrorCode::ParseError, doc.name(), e.line,
				 "'%s' is %d x %d, expected %d x %d", e.key.c_str(), m.rows, m.cols,
				 rows, cols);
	for (int i = 0; i < rows * cols; i++)
		out[i] = m.data[i];
	return Status::success();
}

Status readDistortion(const YamlDocument &doc, const YamlEntry &e, OpenCvDistortion &d)
{
	YamlDocument::Matrix m;
	Status st = doc.matrix(e, m);
	if (!st.ok())
		return st;
	const int n = m.rows * m.cols;
	if ((m.rows != 1 && m.cols != 1) || (n != 4 && n != 5 && n != 8 && n != 12 && n != 14))
		return fileError(ErrorCode::ParseError, doc.name(), e.line,
				 "'%s' is %d x %d, expected 4, 5, 8, 12 or 14 coefficients in a "
				 "row or column",
				 e.key.c_str(), m.rows, m.cols);
	// The rational, thin-prism and tilt terms are not modelled: accept them only when zero.
	for (int i = 5; i < n; i++)
		if (m.data[i] != 0.0)
			return fileError(ErrorCode::InvalidArgument, doc.name(), e.line,
					 "'%s': coefficient %d is %g; only k1 k2 p1 p2 k3 are "
					 "supported (the others must be 0)",
					 e.key.c_str(), i, m.data[i]);
	d.k1 = m.data[0];
	d.k2 = m.data[1];
	d.p1 = m.data[2];
	d.p2 = m.data[3];
	d.k3 = n > 4 ? m.data[4] : 0.0;
	return Status::success();
}

Status load(const char *data, size_t size, const char *name, CameraModel &out)
{
	YamlDocument doc;
	Status st = doc.parse(data, size, name);
	if (!st.ok())
		return st;

	const YamlEntry *kEntry = findAny(doc, { "camera_matrix", "cameraMatrix" });
	if (!kEntry)
		return fileError(ErrorCode::ParseError, name, 0, "missing camera_matrix");
	double k[9];
	st = readMatrix(doc, *kEntry, 3, 3, k);
	if (!st.ok())
		return st;
	Eigen::Matrix3d K;
	K << k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8];

	OpenCvDistortion dist;
	if (const YamlEntry *e =
		    findAny(doc, { "distortion_coefficients", "dist_coeffs", "distCoeffs" })) {
		st = readDistortion(doc, *e, dist);
		if (!st.ok())
			return st;
	}

	const YamlEntry *rvec = doc.find("rvec");
	const YamlEntry *tvec = doc.find("tvec");
	const YamlEntry *Rm = doc.find("R");
	const YamlEntry *tm = doc.find("t");
	if ((rvec || tvec) && (Rm || tm))
		return fileError(ErrorCode::ParseError, name, (rvec ? rvec : tvec)->line,
				 "both rvec/tvec and R/t given: keep one pair");
	if (!rvec && !tvec && !Rm && !tm)
		return fileError(ErrorCode::ParseError, name, 0,
				 "missing the pose: rvec and tvec, or R and t");
	if ((rvec || Rm) && !(tvec || tm))
		return fileError(ErrorCode::ParseError, name, (rvec ? rvec : Rm)->line,
				 "%s without %s", rvec ? "rvec" : "R", rvec ? "tvec" : "t");
	if (!(rvec || Rm))
		return fileError(ErrorCode::ParseError, name, (tvec ? tvec : tm)->line,
				 "%s without %s", tvec ? "tvec" : "t", tvec ? "rvec" : "R");

	Eigen::Matrix3d R;
	Eigen::Vector3d t;
	if (rvec) {
		Eigen::Vector3d r;
		st = readMatrix(doc, *rvec, 3, 1, r.data());
		if (!st.ok())
			return st;
		R = calib::rotationFromRodrigues(r);
	} else {
		double r[9];
		st = readMatrix(doc, *Rm, 3, 3, r);
		if (!st.ok())
			return st;
		R << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
		if (!calib::isRotation(R, 1e-6))
			return fileError(ErrorCode::InvalidArgument, name, Rm->line,
					 "R is not a rotation matrix (R^T R != I or det R != 1)");
	}
	st = readMatrix(doc, *(tvec ? tvec : tm), 3, 1, t.data());
	if (!st.ok())
		return st;

	const YamlEntry *unitEntry = doc.find("unit");
	if (!unitEntry)
		return fileError(ErrorCode::ParseError, name, 0,
				 "missing 'unit: mm|cm|m' (the unit of %s)", tvec ? "tvec" : "t");
	std::string u;
	st = doc.scalar(*unitEntry, u);
	if (!st.ok())
		return st;
	LengthUnit unit;
	if (!parseLengthUnit(u.data(), u.size(), unit)) {
		char q[32];
		return fileError(ErrorCode::ParseError, name, unitEntry->line,
				 "unknown unit '%s' (expected mm, cm or m)",
				 calib::quote(u, q, sizeof(q)));
	}
	return calib::withFileName(CameraModel::fromOpenCv(K, R, t, dist, unit, out), name);
}

} // namespace

Status loadOpenCvYaml(const char *data, size_t size, const char *name, CameraModel &out)
{
	try {
		return load(data, size, name, out);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: out of memory", name);
	}
}

} // namespace calped
