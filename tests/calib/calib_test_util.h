// SPDX-License-Identifier: BSD-2-Clause
// Shared helpers of the calibration tests: files, the synthetic cameras and the PETS
// ground truth.
#pragma once

#include <string>
#include <vector>

#include <calped/calibration.h>

namespace calped::calib_test {

// Whole file as text; false when it cannot be read.
bool readFile(const std::string &path, std::string &out);
// tests/calib/data/<name> in the source tree.
std::string dataPath(const std::string &name);
// ../shared/<relative>, or "" when ../shared is absent (the caller skips).
std::string sharedPath(const std::string &relative);

// Loads a text buffer with the auto-detecting loader (name "<test>").
Status loadText(const std::string &text, CameraModel &out);
// Loads tests/calib/data/<name>; fails the test on error.
CameraModel loadData(const std::string &name);

// A camera 5 m above the ground looking horizontally along +y; f = 1000 px, principal
// point (640, 360). Hand-computable: a ground point at distance Z is on row 360 + 5000 / Z.
CameraModel levelCamera();
// The "pitched" camera of tests/calib/data: centre (0, 0, 10) m, looking along +y 30
// degrees down, f = 1000 px, principal point (640, 360).
Eigen::Matrix3d pitchedK();
Eigen::Matrix3d pitchedR();
Eigen::Vector3d pitchedT(); // metres
CameraModel pitchedCamera();

// Ground-truth box of the PETS CVML file, pixels.
struct GtBox {
	int frame = 0;
	double xc = 0, yc = 0, w = 0, h = 0;
	Eigen::Vector2d foot() const { return Eigen::Vector2d(xc, yc + h / 2); }
	Eigen::Vector2d head() const { return Eigen::Vector2d(xc, yc - h / 2); }
};
// Reads every <frame number> / <object> / <box> of a CVML file; false on any error.
bool readCvml(const std::string &path, std::vector<GtBox> &out, std::string &error);

// `text` with the first `from` replaced by `to` (fails the test when absent).
std::string edit(const std::string &text, const std::string &from, const std::string &to);
// `text` without the lines containing `what`.
std::string dropLines(const std::string &text, const std::string &what);

using Loader = Status (*)(const char *, size_t, const char *, CameraModel &);

// One malformed input and the error it must give.
struct BadInput {
	const char *label;
	std::string text;
	ErrorCode code;
	const char *expected; // substring of the message
};
// Runs each case through `load`: the code and substring must match, the message must name
// the file, and no two cases may give the same message.
void expectErrors(Loader load, const std::vector<BadInput> &cases);

// Sorted-copy statistics.
struct Summary {
	double min = 0, median = 0, max = 0;
};
Summary summarise(std::vector<double> values);

} // namespace calped::calib_test
