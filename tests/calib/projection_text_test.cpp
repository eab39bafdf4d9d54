// SPDX-License-Identifier: BSD-2-Clause
// Plain projection-matrix text: units, comments, the writer's round trip, malformed variants.
#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

TEST(ProjectionText, MillimetreFile)
{
	const CameraModel m = loadData("pitched_P_mm.txt");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Millimetre);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_NEAR(m.centre().z(), 10.0, 1e-9);
	EXPECT_FALSE(m.hasPinhole());
	EXPECT_EQ(m.distortionModel(), DistortionModel::None);
}

TEST(ProjectionText, MetreFileWithCommasAndComments)
{
	const CameraModel m = loadData("pitched_P_m.txt");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Metre);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(ProjectionText, CentimetresAndScaleDoNotMatter)
{
	Matrix34d P = pitchedCamera().projection();
	P.leftCols<3>() *= 0.01; // acts on centimetres
	P *= -42.0;		 // any scale, any sign
	std::string text;
	ASSERT_TRUE(formatProjectionText(P, LengthUnit::Centimetre, "scaled", text).ok());
	CameraModel m;
	Status st = loadText(text, m);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(ProjectionText, WriterRoundTripIsExact)
{
	const Matrix34d P = pitchedCamera().projection();
	std::string text;
	ASSERT_TRUE(formatProjectionText(P, LengthUnit::Metre, "line one\nline two", text).ok());
	EXPECT_EQ(text.rfind("# line one\n# line two\nunit: m\n", 0), 0u) << text;
	CameraModel m;
	ASSERT_TRUE(loadProjectionText(text.data(), text.size(), "roundtrip", m).ok());
	// %.17g is lossless; the reload only renormalises the scale (last-bit changes).
	EXPECT_LT((m.projection() - P).cwiseAbs().maxCoeff(), 1e-12 * P.cwiseAbs().maxCoeff());
}

TEST(ProjectionText, MalformedInputs)
{
	std::string good;
	ASSERT_TRUE(readFile(dataPath("pitched_P_mm.txt"), good));
	const std::string row3 = "0.0  0.0008660254037844386 -0.0005            5\n";
	const std::string noRow3 = edit(good, row3, "");
	expectErrors(loadProjectionText, {
		{ "truncated", noRow3, ErrorCode::ParseError, "only 2 rows: P is 3x4 (truncated?)" },
		{ "truncated to one row", noRow3.substr(0, noRow3.find("0.0 -0.188")),
		  ErrorCode::ParseError, "only 1 row:" },
		{ "short row", edit(good, "-0.0005            5", "-0.0005"), ErrorCode::ParseError,
		  "row 3 has fewer than 4 numbers" },
		{ "long row", edit(good, "-0.32                3200", "-0.32 3200 1"),
		  ErrorCode::ParseError, "row 1 has more than 4 numbers" },
		{ "four rows", good + "0 0 0 1\n", ErrorCode::ParseError, "more than 3 rows" },
		{ "non-numeric", edit(good, "3200", "3200x"), ErrorCode::ParseError,
		  "P(1,4) '3200x' is not a number" },
		{ "NaN", edit(good, "-0.1882308546376021", "nan"), ErrorCode::ParseError,
		  "P(2,2) 'nan' is not a finite number" },
		{ "singular", edit(edit(good, "1.0  0.5542562584220407 -0.32", "0 0 0"),
				   "0.0 -0.1882308546376021", "0.0 0.0"),
		  ErrorCode::InvalidArgument, "left 3x3 block is singular" },
		{ "all zero", "0 0 0 0\n0 0 0 0\n0 0 0 0\n", ErrorCode::InvalidArgument, "degenerate" },
		{ "unknown unit", edit(good, "unit: mm", "unit: ft"), ErrorCode::ParseError,
		  "unknown unit 'ft' (expected mm, cm or m)" },
		{ "unit twice", good + "unit: m\n", ErrorCode::ParseError, "unit given twice" },
		{ "unit without colon", edit(good, "unit: mm", "unit mm"), ErrorCode::ParseError,
		  "expected 'unit: mm|cm|m'" },
		{ "comments only", "# nothing here\n\n", ErrorCode::ParseError, "no matrix rows" },
		{ "camera underground", "1000 0 640 0\n0 -1000 360 0\n0 0 1 10\n",
		  ErrorCode::InvalidArgument, "not above the ground plane" },
	});
}

} // namespace
} // namespace calped
