// SPDX-License-Identifier: BSD-2-Clause
// calped-detect with --threads above 1: the next image file is decoded on a thread of its
// own while the current frame is detected (decoding a PNG costs about half of what the
// calibrated detector does on it, and would otherwise be the run's serial part).
#pragma once

#include <string>
#include <thread>

#include "image_io.h"

namespace calped::apps {

class ImagePrefetch
{
public:
	~ImagePrefetch() { wait(); }
	// Starts decoding `path` (the previous decode is waited for first).
	void start(const std::string &path);
	// The image started for `path`, moved into `out`: true, or false with `error` when it
	// did not decode. false with an empty error: nothing was started for that path.
	bool take(const std::string &path, ports::RgbImage &out, std::string &error);

private:
	void wait();

	std::thread thread_;
	std::string path_;
	ports::ImageDecoder decoder_;
	ports::RgbImage image_;
	bool ok_ = false;
	std::string error_;
};

} // namespace calped::apps
