// SPDX-License-Identifier: BSD-2-Clause
// Finding a libcamera camera: the process-wide camera manager and the lookup by id or
// index, with the CameraNotFound message that lists what exists.
#pragma once

#include <memory>
#include <string>

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>

#include <calped/status.h>

namespace calped {
namespace ports {

// libcamera aborts the process when a second CameraManager is created, so every source in
// the process shares one, created (and started) on first use and destroyed with the last
// holder. quietLog keeps libcamera's log to errors unless LIBCAMERA_LOG_LEVELS is set.
// Errors: CameraError when the manager does not start.
Status sharedCameraManager(bool quietLog, std::shared_ptr<libcamera::CameraManager> &out);

// The camera whose id is `wanted`, else the one at index `wanted`; empty: the first.
// CameraNotFound lists the cameras (as much as the fixed-size message holds) or says that
// libcamera sees none.
Status findCamera(const libcamera::CameraManager &manager, const std::string &wanted,
		  std::shared_ptr<libcamera::Camera> &out);

} // namespace ports
} // namespace calped
