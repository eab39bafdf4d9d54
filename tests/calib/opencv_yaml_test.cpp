// SPDX-License-Identifier: BSD-2-Clause
// OpenCV FileStorage YAML: block and flow matrices, rvec/tvec and R/t, units, malformed
// variants.
#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

TEST(OpenCvYaml, RvecTvecInMillimetres)
{
	const CameraModel m = loadData("pitched_rvec.yml");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Millimetre);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_LT((m.rotation() - pitchedR()).cwiseAbs().maxCoeff(), 1e-12);
	EXPECT_LT((m.translation() - pitchedT()).cwiseAbs().maxCoeff(), 1e-12); // metres
	EXPECT_EQ(m.distortionModel(), DistortionModel::None); // all five coefficients are 0
}

TEST(OpenCvYaml, RAndTInCentimetresFlowStyle)
{
	const CameraModel m = loadData("pitched_Rt.yml");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Centimetre);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
	ASSERT_EQ(m.distortionModel(), DistortionModel::OpenCv);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().k1, -0.2);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().p2, -0.0005);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().k3, 0.0);
}

TEST(OpenCvYaml, EightCoefficientsWithZeroExtras)
{
	std::string text;
	ASSERT_TRUE(readFile(dataPath("pitched_rvec.yml"), text));
	text = edit(edit(text, "cols: 5", "cols: 8"), "data: [ 0., 0., 0., 0., 0. ]",
		    "data: [ 0.1, 0., 0., 0., 0., 0., 0., 0. ]");
	CameraModel m;
	Status st = loadOpenCvYaml(text.data(), text.size(), "eight.yml", m);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_DOUBLE_EQ(m.openCvDistortion().k1, 0.1);
}

TEST(OpenCvYaml, MalformedInputs)
{
	std::string good;
	ASSERT_TRUE(readFile(dataPath("pitched_rvec.yml"), good));
	const std::string camBlock = "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n";
	expectErrors(loadOpenCvYaml, {
		{ "truncated", good.substr(0, good.find("5.0000000000000000e+03")),
		  ErrorCode::ParseError, "is not closed with ']' or '}' (truncated?)" },
		{ "truncated matrix", good.substr(0, good.find("   data: [ 1000.")),
		  ErrorCode::ParseError, "'camera_matrix' lacks 'data'" },
		{ "missing camera matrix",
		  edit(good, camBlock, "old_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n"),
		  ErrorCode::ParseError, "missing camera_matrix" },
		{ "missing unit", dropLines(good, "unit: mm"), ErrorCode::ParseError,
		  "missing 'unit: mm|cm|m' (the unit of tvec)" },
		{ "unknown unit", edit(good, "unit: mm", "unit: inch"), ErrorCode::ParseError,
		  "unknown unit 'inch'" },
		{ "non-numeric", edit(good, "640.,", "64O.,"), ErrorCode::ParseError,
		  "camera_matrix data[2] '64O.' is not a number" },
		{ "NaN", edit(good, "2.0943951023931953", ".nan"), ErrorCode::ParseError,
		  "rvec data[0] '.nan' is not a finite number" },
		{ "wrong row count", edit(edit(good, camBlock, "camera_matrix: !!opencv-matrix\n   rows: 2\n   cols: 3\n"),
					  "data: [ 1000., 0., 640., 0., 1000., 360., 0., 0., 1. ]",
					  "data: [ 1000., 0., 640., 0., 1000., 360. ]"),
		  ErrorCode::ParseError, "'camera_matrix' is 2 x 3, expected 3 x 3" },
		{ "data count", edit(good, "0., 0., 1. ]", "0., 1. ]"), ErrorCode::ParseError,
		  "has 8 values in data but rows x cols = 3 x 3" },
		{ "both poses", good + "R: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 1, 0, 0, 0, 1, 0, 0, 0, 1 ]\n",
		  ErrorCode::ParseError, "both rvec/tvec and R/t given" },
		{ "rvec without tvec", edit(good, "tvec:", "tvec_old:"),
		  ErrorCode::ParseError, "rvec without tvec" },
		{ "no pose", good.substr(0, good.find("rvec:")) + "unit: mm\n", ErrorCode::ParseError,
		  "missing the pose" },
		{ "R not a rotation",
		  good.substr(0, good.find("rvec:")) +
			  "R: !!opencv-matrix { rows: 3, cols: 3, dt: d, data: [ 1, 0, 0, 0, 2, 0, 0, 0, 1 ] }\n"
			  "t: !!opencv-matrix { rows: 3, cols: 1, dt: d, data: [ 0, 0, 5 ] }\nunit: m\n",
		  ErrorCode::InvalidArgument, "R is not a rotation matrix" },
		{ "unsupported dt", edit(good, "dt: d\n   data: [ 1000.", "dt: u\n   data: [ 1000."),
		  ErrorCode::ParseError, "dt 'u' is not supported" },
		{ "no header", edit(good, "%YAML:1.0\n", ""), ErrorCode::ParseError,
		  "missing the '%YAML:1.0' header" },
		{ "sequence", good + "points:\n  - 1\n  - 2\n", ErrorCode::ParseError,
		  "sequences ('- item') are not supported" },
		{ "duplicate key", good + "unit: m\n", ErrorCode::ParseError,
		  "unit given twice (first on line" },
		{ "extra distortion terms", edit(edit(good, "cols: 5", "cols: 8"),
						 "data: [ 0., 0., 0., 0., 0. ]",
						 "data: [ 0., 0., 0., 0., 0., 0.5, 0., 0. ]"),
		  ErrorCode::InvalidArgument, "only k1 k2 p1 p2 k3 are supported" },
		{ "lower-triangular K", edit(good, "0., 1000., 360.", "5., 1000., 360."),
		  ErrorCode::InvalidArgument, "not upper triangular" },
		{ "not a matrix", edit(good, "rvec: !!opencv-matrix", "rvec: 3"),
		  ErrorCode::ParseError, "'rvec' must be an !!opencv-matrix" },
		{ "unknown matrix field", edit(good, "   dt: d\n   data: [ 2.09", "   type: d\n   data: [ 2.09"),
		  ErrorCode::ParseError, "unknown field 'type'" },
		{ "unclosed quote", edit(good, "CET\"", "CET"), ErrorCode::ParseError,
		  "quoted string is not closed" },
		// Found by fuzzing: a row count beyond int was cast before the range check (UB).
		{ "rows beyond int", edit(good, camBlock, "camera_matrix: !!opencv-matrix\n   rows: 3.11111e10\n   cols: 3\n"),
		  ErrorCode::ParseError, "rows '3.11111e10' is not a whole number in 1..64" },
		// Found by fuzzing: keys quoted in messages keep no control characters.
		{ "control characters in a key", good + "\x1b" "key\x07 x\n", ErrorCode::ParseError,
		  "expected ':' after the key '?key?'" },
	});
}

} // namespace
} // namespace calped
