// SPDX-License-Identifier: BSD-2-Clause
// Town Centre ".ci" text: the synthetic camera, the real Town Centre file, malformed variants.
#include <cmath>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

TEST(TownCentreCi, SyntheticCameraMatchesPinhole)
{
	const CameraModel m = loadData("pitched.ci");
	ASSERT_TRUE(m.valid());
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
	EXPECT_LT((m.rotation() - pitchedR()).cwiseAbs().maxCoeff(), 1e-12);
	EXPECT_EQ(m.distortionModel(), DistortionModel::None);
	EXPECT_EQ(m.sourceUnit(), LengthUnit::Metre);
}

TEST(TownCentreCi, SyntheticCameraWithDistortion)
{
	const CameraModel m = loadData("pitched_distorted.ci");
	ASSERT_TRUE(m.valid());
	EXPECT_EQ(m.distortionModel(), DistortionModel::OpenCv);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().k1, -0.2);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().p2, -0.0005);
	EXPECT_DOUBLE_EQ(m.openCvDistortion().k3, 0.0);
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(TownCentreCi, LoadsTheTownCentreFile)
{
	const std::string path = sharedPath("data/towncentre/TownCentre-calibration-ci.txt");
	if (path.empty())
		GTEST_SKIP() << "../shared/data/towncentre/TownCentre-calibration-ci.txt not found "
				"(CALPED_SHARED_DIR); Town Centre calibration not tested";
	std::string text;
	ASSERT_TRUE(readFile(path, text));
	EXPECT_EQ(detectCalibrationFormat(text.data(), text.size()),
		  CalibrationFormat::TownCentreCi);
	CameraModel m;
	Status st = loadCalibration(text.data(), text.size(), "TownCentre-calibration-ci.txt", m);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(m.distortionModel(), DistortionModel::OpenCv);
	// Read as world -> camera (X_cam = R X + t), the camera is ~8 m above a street it
	// looks down on; people are ~110 px tall at the top of the 1920 x 1080 frame and ~280 px
	// at the bottom, as in the video.
	EXPECT_GT(m.centre().z(), 5.0);
	EXPECT_LT(m.centre().z(), 12.0);
	EXPECT_LT(m.horizonRow(960), 0.0);
	const double top = m.boxPixelHeight(Eigen::Vector2d(960, 100), 1.75);
	const double bottom = m.boxPixelHeight(Eigen::Vector2d(960, 1079), 1.75);
	EXPECT_GT(top, 80.0);
	EXPECT_LT(bottom, 400.0);
	EXPECT_LT(top, bottom);
	double worst = 0;
	for (double y = 0; y <= 1080; y += 60)
		for (double x = 0; x <= 1920; x += 60) {
			const Eigen::Vector2d p(x, y);
			worst = std::max(worst, (m.distort(m.undistort(p)) - p).norm());
		}
	EXPECT_LT(worst, 1e-8);
	std::printf("    Town Centre: centre (%.3f, %.3f, %.3f) m; 1.75 m person %.1f px at row 100, "
		    "%.1f px at row 1079\n",
		    m.centre().x(), m.centre().y(), m.centre().z(), top, bottom);
}

TEST(TownCentreCi, MalformedInputs)
{
	std::string good;
	ASSERT_TRUE(readFile(dataPath("pitched.ci"), good));
	expectErrors(loadTownCentreCi, {
		{ "truncated", good.substr(0, good.find("RotationW")), ErrorCode::ParseError,
		  "missing key RotationW" },
		{ "missing field", dropLines(good, "Skew"), ErrorCode::ParseError, "missing key Skew" },
		{ "non-numeric", edit(good, "= 640.0", "= 640px"), ErrorCode::ParseError,
		  "PrincipalPointX '640px' is not a number" },
		{ "NaN", edit(good, "DistortionK2 = 0.0", "DistortionK2 = NaN"), ErrorCode::ParseError,
		  "DistortionK2 'NaN' is not a finite number" },
		{ "unknown key", edit(good, "Skew", "Skw"), ErrorCode::ParseError, "unknown key 'Skw'" },
		{ "duplicate key", good + "RotationW = 0.5\n", ErrorCode::ParseError,
		  "RotationW given twice (first on line 12)" },
		{ "no equals sign", edit(good, "Skew = 0.0", "Skew 0.0"), ErrorCode::ParseError,
		  "expected 'Key = value'" },
		{ "empty value", edit(good, "Skew = 0.0", "Skew ="), ErrorCode::ParseError,
		  "Skew '' is not a number" },
		{ "non-unit quaternion", edit(good, "RotationW = 0.5", "RotationW = 0.9"),
		  ErrorCode::InvalidArgument, "quaternion has norm" },
		{ "negative focal", edit(good, "FocalLengthY = 1000.0", "FocalLengthY = -1000.0"),
		  ErrorCode::InvalidArgument, "focal lengths 1000, -1000 must be > 0" },
		{ "camera underground", edit(edit(good, "TranslationZ = 5.0", "TranslationZ = -5.0"),
				       "TranslationY = 8", "TranslationY = -8"),
		  ErrorCode::InvalidArgument, "not above the ground plane" },
	});
}

} // namespace
} // namespace calped
