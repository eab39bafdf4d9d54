// SPDX-License-Identifier: BSD-2-Clause
// CameraModel::checkFrameSize: a calibration made for frames of another size is an error
// naming both sizes (the detector, the programs and the GStreamer element share it).
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include <calped/calibration.h>
#include <calped/detector.h>

#include "calib_test_util.h"

namespace calped {
namespace {

using namespace calib_test;

TEST(FrameSize, TsaiStatedSizeMustBeTheFrames)
{
	const CameraModel cam = loadData("pitched_tsai.xml");
	ASSERT_GT(cam.imageWidth(), 0);
	const int w = cam.imageWidth(), h = cam.imageHeight();
	EXPECT_TRUE(cam.checkFrameSize(w, h).ok());
	const Status st = cam.checkFrameSize(w / 2, h / 2);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	const std::string both = "is for " + std::to_string(w) + "x" + std::to_string(h) +
				 " images, the frames are " + std::to_string(w / 2) + "x" + std::to_string(h / 2);
	EXPECT_NE(std::strstr(st.message(), both.c_str()), nullptr) << st.message();
}

// The Town Centre case: a .ci file states no size; its principal point (959.5, 539.5) lies
// outside 768x576 frames.
TEST(FrameSize, PrincipalPointOutsideTheFramesIsAnotherSize)
{
	Eigen::Matrix3d K = pitchedK();
	K(0, 2) = 959.5;
	K(1, 2) = 539.5;
	CameraModel cam;
	ASSERT_TRUE(CameraModel::fromPinhole(K, pitchedR(), pitchedT(), LengthUnit::Metre, cam).ok());
	EXPECT_EQ(cam.imageWidth(), 0);
	EXPECT_TRUE(cam.checkFrameSize(1920, 1080).ok());
	EXPECT_TRUE(cam.checkFrameSize(960, 540).ok()); // on the edge is still inside
	const Status st = cam.checkFrameSize(768, 576);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::strstr(st.message(), "principal point (959.5, 539.5) is outside the 768x576 frames"),
		  nullptr) << st.message();
	EXPECT_NE(std::strstr(st.message(), "1920x1080"), nullptr) << st.message();
	EXPECT_FALSE(cam.checkFrameSize(1920, 500).ok());

	// The detector refuses it the same way (DetectorConfig::validate).
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.camera = &cam;
	const Status v = cfg.validate();
	EXPECT_EQ(v.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::strstr(v.message(), "principal point"), nullptr) << v.message();
}

// A bare projection matrix states neither a size nor intrinsics: nothing to check.
TEST(FrameSize, BareProjectionIsNotChecked)
{
	const CameraModel cam = loadData("pitched_P_m.txt");
	EXPECT_FALSE(cam.hasPinhole());
	EXPECT_TRUE(cam.checkFrameSize(10, 10).ok());
}

} // namespace
} // namespace calped
