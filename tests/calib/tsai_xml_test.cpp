// SPDX-License-Identifier: BSD-2-Clause
// Tsai XML (PETS 2009 layout): the synthetic camera, PETS's own file, malformed variants.
#include <cmath>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

std::string pitchedXml()
{
	std::string text;
	EXPECT_TRUE(readFile(dataPath("pitched_tsai.xml"), text));
	return text;
}

TEST(TsaiXml, SyntheticCameraMatchesPinhole)
{
	const CameraModel m = loadData("pitched_tsai.xml");
	const CameraModel ref = pitchedCamera();
	ASSERT_TRUE(m.valid());
	EXPECT_LT((m.projection() - ref.projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Millimetre);
	EXPECT_EQ(m.distortionModel(), DistortionModel::None);
	EXPECT_EQ(m.imageWidth(), 1280);
	EXPECT_EQ(m.imageHeight(), 720);
	EXPECT_NEAR(m.centre().z(), 10.0, 1e-9); // millimetres in the file, metres here
	ASSERT_TRUE(m.hasPinhole());
	EXPECT_NEAR(m.intrinsics()(0, 0), 1000.0, 1e-9);
}

TEST(TsaiXml, SyntheticCameraWithKappa)
{
	const CameraModel m = loadData("pitched_tsai_kappa.xml");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.distortionModel(), DistortionModel::TsaiRadial);
	EXPECT_DOUBLE_EQ(m.tsaiKappa1(), 0.005);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
	// A corner pixel moves outwards when undistorted (kappa1 > 0: barrel).
	const Eigen::Vector2d u = m.undistort(Eigen::Vector2d(0, 0));
	EXPECT_LT(u.x(), 0.0);
	EXPECT_LT(u.y(), 0.0);
}

TEST(TsaiXml, ParsesPetsView001)
{
	const std::string path = sharedPath("data/pets2009-s2l1/View_001.xml");
	if (path.empty())
		GTEST_SKIP() << "../shared/data/pets2009-s2l1/View_001.xml not found "
				"(CALPED_SHARED_DIR); PETS calibration not tested";
	std::string text;
	ASSERT_TRUE(readFile(path, text));
	TsaiCamera c;
	Status st = parseTsaiXml(text.data(), text.size(), "View_001.xml", c);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(c.width, 768);
	EXPECT_EQ(c.height, 576);
	EXPECT_DOUBLE_EQ(c.focal, 5.5549183034);
	EXPECT_DOUBLE_EQ(c.kappa1, 5.1113043639e-03);
	EXPECT_DOUBLE_EQ(c.sx, 1.0937855397);
	EXPECT_DOUBLE_EQ(c.tz, 3.5469298547e+04);
	EXPECT_DOUBLE_EQ(c.rz, -4.3056124791e-01);
	// The file's dpx is Tsai's dx * ncx / nfx.
	EXPECT_NEAR(c.dpx, c.dx * c.ncx / c.nfx, 1e-12);

	CameraModel m;
	st = loadTsaiXml(text.data(), text.size(), "View_001.xml", m);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(m.distortionModel(), DistortionModel::TsaiRadial);
	// The camera looks down on the square from a few metres up.
	EXPECT_GT(m.centre().z(), 4.0);
	EXPECT_LT(m.centre().z(), 12.0);
	EXPECT_LT(m.horizonRow(384), 0.0); // horizon above the image
	std::printf("    PETS View_001: centre (%.3f, %.3f, %.3f) m, horizon row %.1f at u = 384\n",
		    m.centre().x(), m.centre().y(), m.centre().z(), m.horizonRow(384));
}

TEST(TsaiXml, ErrorLinesPointAtTheField)
{
	// Line 7 holds <Intrinsic>; the error must say so.
	const std::string bad = edit(pitchedXml(), "focal=\"5.0\"", "focal=\"5,0\"");
	CameraModel m;
	Status st = loadTsaiXml(bad.data(), bad.size(), "pitched_tsai.xml", m);
	EXPECT_EQ(st.code(), ErrorCode::ParseError);
	EXPECT_NE(std::string(st.message()).find("pitched_tsai.xml:7:"), std::string::npos)
		<< st.message();
}

TEST(TsaiXml, MalformedInputs)
{
	const std::string good = pitchedXml();
	expectErrors(loadTsaiXml, {
		{ "truncated", good.substr(0, good.size() / 2), ErrorCode::ParseError, "truncated" },
		{ "truncated in tag", good.substr(0, good.find("sx=")), ErrorCode::ParseError,
		  "inside the tag <Intrinsic>" },
		{ "missing attribute", edit(good, "dpy=\"0.005\"", ""), ErrorCode::ParseError,
		  "lacks attribute 'dpy'" },
		{ "non-numeric", edit(good, "focal=\"5.0\"", "focal=\"five\""),
		  ErrorCode::ParseError, "'five' is not a number" },
		{ "NaN", edit(good, "kappa1=\"0\"", "kappa1=\"nan\""), ErrorCode::ParseError,
		  "kappa1 'nan' is not a finite number" },
		{ "infinite", edit(good, "tz=\"5000\"", "tz=\"1e400\""), ErrorCode::ParseError,
		  "tz '1e400' is not a finite number" },
		{ "missing element", dropLines(good, "<Extrinsic"), ErrorCode::ParseError,
		  "has no <Extrinsic>" },
		{ "duplicate element",
		  edit(good, "<Extrinsic", "<Intrinsic focal=\"5.0\" kappa1=\"0\" cx=\"640\" cy=\"360\" sx=\"1.0\"/>\n\t<Extrinsic"),
		  ErrorCode::ParseError, "second <Intrinsic>" },
		{ "zero focal", edit(good, "focal=\"5.0\"", "focal=\"0\""), ErrorCode::InvalidArgument,
		  "focal = 0 must be > 0" },
		{ "negative pixel", edit(good, "dpx=\"0.005\"", "dpx=\"-0.005\""),
		  ErrorCode::InvalidArgument, "dpx = -0.005 must be > 0" },
		{ "wrong root", edit(edit(good, "<Camera name", "<Kamera name"), "</Camera>", "</Kamera>"),
		  ErrorCode::ParseError, "expected <Camera>" },
		{ "mismatched tag", edit(good, "</Camera>", "</Camara>"), ErrorCode::ParseError,
		  "does not match <Camera>" },
		{ "unknown attribute", edit(good, "sx=\"1.0\"", "sx=\"1.0\" sy=\"1.0\""),
		  ErrorCode::ParseError, "unknown attribute 'sy'" },
		{ "unknown element", edit(good, "</Camera>", "<Lens/>\n</Camera>"),
		  ErrorCode::ParseError, "unknown element <Lens>" },
		{ "nested element", edit(good, "rz=\"0\"/>", "rz=\"0\"><x/></Extrinsic>"),
		  ErrorCode::ParseError, "<Extrinsic> may not contain elements" },
		{ "duplicate attribute", edit(good, "sx=\"1.0\"", "sx=\"1.0\" sx=\"2\""),
		  ErrorCode::ParseError, "duplicate attribute 'sx'" },
		{ "text content", edit(good, "</Camera>", "hello\n</Camera>"),
		  ErrorCode::ParseError, "unexpected text 'hello'" },
		{ "doctype", edit(good, "<!--", "<!DOCTYPE camera>\n<!--"), ErrorCode::ParseError,
		  "DOCTYPE" },
		{ "unquoted value", edit(good, "cx=\"640\"", "cx=640"), ErrorCode::ParseError,
		  "must be quoted" },
		{ "bad entity", edit(good, "name=\"pitched\"", "name=\"a&b\""),
		  ErrorCode::ParseError, "'&' does not start an entity" },
		{ "unclosed comment", edit(good, "-->", "--"), ErrorCode::ParseError,
		  "comment is not closed" },
		{ "second root", good + "<Camera/>\n", ErrorCode::ParseError,
		  "content after the root element" },
		{ "empty", "", ErrorCode::ParseError, "no root element" },
		{ "late declaration", "\n<!-- x -->\n" + good, ErrorCode::ParseError,
		  "declaration must come first" },
	});
}

} // namespace
} // namespace calped
