// SPDX-License-Identifier: BSD-2-Clause
// Where frames come from: a folder of images (sorted by name) or a video decoded on the fly
// by the file port's ffmpeg pipe (ports/file/video_pipe.h). Frames are numbered 1..N.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image_io.h"

namespace calped::eval_tool {

using ports::RgbImage;

class FrameSource
{
public:
	virtual ~FrameSource() = default;
	// Decodes the next frame. Returns false at the end of the input (error left empty)
	// or on failure (error set).
	virtual bool next(RgbImage &image, std::string &error) = 0;
};

// The resolved input, decided once in the harness and then opened by every run.
struct FrameInput {
	std::vector<std::string> files; // folder mode
	std::string video;              // video mode
	int width = 0, height = 0;      // video frame size; largest image size in folder mode
	long maxFrames = 0;             // 0 = all

	bool isVideo() const { return !video.empty(); }
	// Frames a run will see: known up front for a folder, -1 for a video.
	long knownFrames() const { return isVideo() ? -1 : static_cast<long>(files.size()); }
	// "frame 12 (data/pets/frames/000012.png)" or "frame 12 of vtest.avi".
	std::string label(long frame) const;
	// The image file of a frame, or the video.
	std::string file(long frame) const;
	std::unique_ptr<FrameSource> open(std::string &error) const;
};

// Lists the folder's images (as calped-detect does), keeps the first maxFrames and reads
// their headers for the largest size.
bool resolveFolderInput(const std::string &dir, long maxFrames, FrameInput &out,
			std::string &error);

// `size` is "WxH" or empty to ask ffprobe.
bool resolveVideoInput(const std::string &path, const std::string &size, long maxFrames,
		       FrameInput &out, std::string &error);


} // namespace calped::eval_tool
