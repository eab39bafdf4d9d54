// SPDX-License-Identifier: BSD-2-Clause
// A FrameSource on a libcamera camera (Raspberry Pi cameras, UVC webcams, ... on Linux).
// Frames are lent straight from the camera's mapped buffers, without a copy; the drop
// policy, the failures and the threads are described in docs/libcamera.md.
// This header does not need libcamera's headers.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <calped/image.h>
#include <calped/status.h>

#include "frame_source.h"

namespace calped {
namespace ports {

struct LibcameraOptions {
	// Camera id as libcamera lists it (`cam --list`), or its index in that list.
	// Empty: the first camera.
	std::string camera;
	// NV12, YUV420, YUYV, BGR8 (libcamera "RGB888"), RGB8 ("BGR888"), Gray8 ("R8") or a
	// Bayer format (raw streams). Unset: the first of NV12, YUV420, YUYV, BGR8, RGB8, Gray8
	// that the camera offers.
	std::optional<PixelFormat> format;
	// Frame size; 0 x 0 keeps the camera's default for the stream. The camera may adjust
	// it to the nearest size it supports (name() then shows both).
	int width = 0;
	int height = 0;
	// Frames per second through libcamera's FrameDurationLimits control; 0 keeps the
	// camera's default. A camera without that control rejects a rate (CameraError).
	double fps = 0;
	// Buffers in the pool (2..16): one lent to the detector, one waiting, the rest queued
	// at the camera. The camera may ask for more.
	int buffers = 4;
	// No complete frame for this long while streaming: next() returns CameraLost (a
	// stalled sensor or pipeline that libcamera does not report). 0: never.
	int lostAfterMs = 10000;
	// Keeps libcamera's own log to errors (LIBCAMERA_LOG_LEVELS=*:ERROR) unless the user
	// set LIBCAMERA_LOG_LEVELS.
	bool quietLibcameraLog = true;
};

// Opens, configures and maps a camera; streaming begins with start(). Errors:
// CameraNotFound (no camera matches options.camera: the message lists the cameras, or says
// that libcamera found none), CameraError (in use, a format/size/rate it refuses, buffer
// allocation or mapping), InvalidArgument (an option out of range).
// Call next(), release(), stop() and the destructor from one thread.
Status openLibcameraSource(const LibcameraOptions &options, std::unique_ptr<FrameSource> &out);

} // namespace ports
} // namespace calped
