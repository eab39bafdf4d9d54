// SPDX-License-Identifier: BSD-2-Clause
// Opening the libcamera port where libcamera finds no camera (CI, containers, most build
// machines): a clear CameraNotFound. Skipped only where a real camera exists.
#include <cstring>
#include <memory>

#include <gtest/gtest.h>

#include "libcamera_source.h"

namespace calped {
namespace ports {
namespace {

TEST(LibcameraNoCamera, OpeningTheFirstCameraSaysNoneExists)
{
	LibcameraOptions options;
	std::unique_ptr<FrameSource> source;
	Status st = openLibcameraSource(options, source);
	if (st.ok())
		GTEST_SKIP() << "a real camera exists here: " << source->name();
	if (st.code() != ErrorCode::CameraNotFound)
		GTEST_SKIP() << "a camera exists but cannot be opened: " << st.message();
	EXPECT_EQ(source, nullptr);
	EXPECT_NE(std::strstr(st.message(), "CameraNotFound: libcamera found no camera"), nullptr)
		<< st.message();
	EXPECT_NE(std::strstr(st.message(), "cam --list"), nullptr) << st.message();
	EXPECT_EQ(std::strchr(st.message(), '\n'), nullptr) << "one line";
}

// True whether or not cameras exist: the message names what was asked for and either
// lists the cameras or says there are none.
TEST(LibcameraNoCamera, UnknownIdIsNamedInTheMessage)
{
	LibcameraOptions options;
	options.camera = "/base/soc/i2c0mux/i2c@1/no-such-sensor@10";
	std::unique_ptr<FrameSource> source;
	Status st = openLibcameraSource(options, source);
	EXPECT_EQ(st.code(), ErrorCode::CameraNotFound) << st.message();
	EXPECT_NE(std::strstr(st.message(), "no-such-sensor@10"), nullptr) << st.message();
	bool none = std::strstr(st.message(), "found no camera") != nullptr;
	bool listed = std::strstr(st.message(), "exist:") != nullptr;
	EXPECT_TRUE(none || listed) << st.message();
}

TEST(LibcameraNoCamera, IndexBeyondTheListIsNotFound)
{
	LibcameraOptions options;
	options.camera = "99";
	std::unique_ptr<FrameSource> source;
	Status st = openLibcameraSource(options, source);
	EXPECT_EQ(st.code(), ErrorCode::CameraNotFound) << st.message();
	EXPECT_NE(std::strstr(st.message(), "'99'"), nullptr) << st.message();
}

// libcamera aborts when two camera managers exist at once; sources share one and it is
// rebuilt after the last one goes, so opening again and again is fine.
TEST(LibcameraNoCamera, RepeatedOpensShareAndRebuildTheCameraManager)
{
	for (int i = 0; i < 3; ++i) {
		LibcameraOptions options;
		options.camera = "no-such-camera";
		std::unique_ptr<FrameSource> source;
		EXPECT_EQ(openLibcameraSource(options, source).code(), ErrorCode::CameraNotFound);
	}
}

TEST(LibcameraNoCamera, OptionsAreCheckedBeforeLookingForACamera)
{
	std::unique_ptr<FrameSource> source;
	LibcameraOptions buffers;
	buffers.buffers = 1;
	Status st = openLibcameraSource(buffers, source);
	EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
	EXPECT_NE(std::strstr(st.message(), "got 1"), nullptr) << st.message();

	LibcameraOptions size;
	size.width = 640;
	EXPECT_EQ(openLibcameraSource(size, source).code(), ErrorCode::InvalidArgument);

	LibcameraOptions lost;
	lost.lostAfterMs = -1;
	EXPECT_EQ(openLibcameraSource(lost, source).code(), ErrorCode::InvalidArgument);

	LibcameraOptions rate;
	rate.fps = -5;
	EXPECT_EQ(openLibcameraSource(rate, source).code(), ErrorCode::InvalidArgument);
	EXPECT_EQ(source, nullptr);
}

} // namespace
} // namespace ports
} // namespace calped
