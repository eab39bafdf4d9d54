// SPDX-License-Identifier: BSD-2-Clause
// Format detection and the same synthetic camera through every format.
#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

TEST(LoadCalibration, DetectsEveryFormat)
{
	const struct {
		const char *file;
		CalibrationFormat format;
	} files[] = {
		{ "pitched_tsai.xml", CalibrationFormat::TsaiXml },
		{ "pitched_tsai_kappa.xml", CalibrationFormat::TsaiXml },
		{ "pitched.ci", CalibrationFormat::TownCentreCi },
		{ "pitched_distorted.ci", CalibrationFormat::TownCentreCi },
		{ "pitched_P_mm.txt", CalibrationFormat::ProjectionText },
		{ "pitched_P_m.txt", CalibrationFormat::ProjectionText },
		{ "pitched_rvec.yml", CalibrationFormat::OpenCvYaml },
		{ "pitched_Rt.yml", CalibrationFormat::OpenCvYaml },
	};
	const CameraModel ref = pitchedCamera();
	for (const auto &f : files) {
		std::string text;
		ASSERT_TRUE(readFile(dataPath(f.file), text)) << f.file;
		EXPECT_EQ(detectCalibrationFormat(text.data(), text.size()), f.format) << f.file;
		CameraModel m;
		Status st = loadCalibration(text.data(), text.size(), f.file, m);
		ASSERT_TRUE(st.ok()) << st.message();
		// Every file describes the same camera: same P, centre and heights.
		EXPECT_LT((m.projection() - ref.projection()).cwiseAbs().maxCoeff(), 1e-9) << f.file;
		EXPECT_NEAR(m.centre().z(), 10.0, 1e-9) << f.file;
		EXPECT_NEAR(m.worldHeight(Eigen::Vector2d(640, 500), Eigen::Vector2d(640, 420)),
			    ref.worldHeight(Eigen::Vector2d(640, 500), Eigen::Vector2d(640, 420)), 1e-9)
			<< f.file;
	}
}

TEST(LoadCalibration, DetectionRules)
{
	auto detect = [](const std::string &s) { return detectCalibrationFormat(s.data(), s.size()); };
	EXPECT_EQ(detect(""), CalibrationFormat::Unknown);
	EXPECT_EQ(detect("\n  # only a comment\n"), CalibrationFormat::Unknown);
	EXPECT_EQ(detect("\xef\xbb\xbf<?xml version=\"1.0\"?>"), CalibrationFormat::TsaiXml);
	EXPECT_EQ(detect("# c\nFocalLengthX = 1"), CalibrationFormat::TownCentreCi);
	EXPECT_EQ(detect("unit: mm\n1 2 3 4"), CalibrationFormat::ProjectionText);
	EXPECT_EQ(detect("%YAML:1.0\n"), CalibrationFormat::OpenCvYaml);
	EXPECT_STREQ(calibrationFormatName(CalibrationFormat::OpenCvYaml), "OpenCV YAML");

	CameraModel m;
	Status st = loadCalibration("# nothing\n", 10, "empty.txt", m);
	EXPECT_EQ(st.code(), ErrorCode::ParseError);
	EXPECT_STREQ(st.message(),
		     "ParseError: empty.txt: empty calibration file (no content besides comments)");
}

TEST(LoadCalibration, Units)
{
	EXPECT_STREQ(lengthUnitName(LengthUnit::Centimetre), "cm");
	EXPECT_DOUBLE_EQ(metresPerUnit(LengthUnit::Millimetre), 0.001);
	LengthUnit u;
	EXPECT_TRUE(parseLengthUnit("m", 1, u));
	EXPECT_EQ(u, LengthUnit::Metre);
	EXPECT_FALSE(parseLengthUnit("M", 1, u));
	EXPECT_FALSE(parseLengthUnit("mm ", 3, u));
}

} // namespace
} // namespace calped
