// SPDX-License-Identifier: BSD-2-Clause
#include "camera_lookup.h"

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

namespace calped {
namespace ports {

namespace {

// The deleter takes the lock too, so a new manager never overlaps a dying one.
std::mutex gManagerMutex;
std::weak_ptr<libcamera::CameraManager> gManager;

bool allDigits(const std::string &s)
{
	if (s.empty())
		return false;
	for (char c : s)
		if (c < '0' || c > '9')
			return false;
	return true;
}

} // namespace

Status sharedCameraManager(bool quietLog, std::shared_ptr<libcamera::CameraManager> &out)
{
	// Declared before the lock: a manager that failed to start is deleted after unlocking
	// (its deleter takes the lock).
	std::shared_ptr<libcamera::CameraManager> manager;
	std::lock_guard<std::mutex> lock(gManagerMutex);
	if ((manager = gManager.lock())) {
		out = manager;
		return Status::success();
	}
	// libcamera reads its log levels once, when it first logs.
	if (quietLog)
		setenv("LIBCAMERA_LOG_LEVELS", "*:ERROR", 0);
	manager.reset(new libcamera::CameraManager(), [](libcamera::CameraManager *m) {
		std::lock_guard<std::mutex> deleting(gManagerMutex);
		delete m; // stops it
	});
	int ret = manager->start();
	if (ret < 0)
		return Status::error(ErrorCode::CameraError,
				     "libcamera's camera manager failed to start: %s",
				     std::strerror(-ret));
	gManager = manager;
	out = manager;
	return Status::success();
}

Status findCamera(const libcamera::CameraManager &manager, const std::string &wanted,
		  std::shared_ptr<libcamera::Camera> &out)
{
	std::vector<std::shared_ptr<libcamera::Camera>> cameras = manager.cameras();
	if (cameras.empty())
		return Status::error(ErrorCode::CameraNotFound,
				     "libcamera found no camera%s%s%s; `cam --list` shows what libcamera "
				     "sees (check that the camera is connected and enabled, and that this "
				     "user may open /dev/media* and /dev/video*)",
				     wanted.empty() ? "" : " (asked for '", wanted.c_str(),
				     wanted.empty() ? "" : "')");
	if (wanted.empty()) {
		out = cameras.front();
		return Status::success();
	}
	for (const auto &camera : cameras) {
		if (camera->id() == wanted) {
			out = camera;
			return Status::success();
		}
	}
	if (allDigits(wanted) && wanted.size() < 6) {
		size_t index = std::strtoul(wanted.c_str(), nullptr, 10);
		if (index < cameras.size()) {
			out = cameras[index];
			return Status::success();
		}
	}
	std::string list;
	for (size_t i = 0; i < cameras.size(); ++i)
		list += (i ? ", " : "") + std::to_string(i) + " '" + cameras[i]->id() + "'";
	return Status::error(ErrorCode::CameraNotFound,
			     "no libcamera camera '%s' (id or index); %zu exist: %s", wanted.c_str(),
			     cameras.size(), list.c_str());
}

} // namespace ports
} // namespace calped
