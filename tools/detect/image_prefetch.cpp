// SPDX-License-Identifier: BSD-2-Clause
#include "image_prefetch.h"

#include <utility>

namespace calped::apps {

void ImagePrefetch::wait()
{
	if (thread_.joinable())
		thread_.join();
}

void ImagePrefetch::start(const std::string &path)
{
	wait();
	path_ = path;
	ok_ = false;
	error_.clear();
	thread_ = std::thread([this] { ok_ = decoder_.decode(path_, image_, error_); });
}

bool ImagePrefetch::take(const std::string &path, ports::RgbImage &out, std::string &error)
{
	error.clear();
	if (!thread_.joinable() || path != path_)
		return false;
	wait();
	if (!ok_) {
		error = error_;
		return false;
	}
	std::swap(out, image_); // both buffers are reused, frame after frame
	return true;
}

} // namespace calped::apps
