// SPDX-License-Identifier: BSD-2-Clause
// A virtual camera over files: an image, a folder of images (PNG, JPEG, PPM, PGM, in name
// order) or a video file (decoded by ffmpeg). Lends RGB8 frames from one buffer sized for
// the largest frame at open(); can loop forever and pace itself at a frame rate.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "frame_source.h"
#include "image_folder.h"
#include "video_pipe.h"

namespace calped {
namespace ports {

struct FileSourceOptions {
	std::string path;   // image file, image folder or video file
	bool loop = false;  // start again after the last frame instead of EndOfStream
	double fps = 0;     // > 0: lend at most this many frames per second (a live camera's pace)
	long maxFrames = 0; // > 0: EndOfStream after this many frames (with or without loop)
};

class FileSource : public FrameSource
{
public:
	// Lists and probes the input (every image header, or the video's size): bad files fail
	// here with IoError naming them; InvalidArgument for a negative fps or frame count.
	static Status open(const FileSourceOptions &options, std::unique_ptr<FileSource> &out);
	~FileSource() override;

	Status start() override;
	Status next(Frame &frame, int timeoutMs) override;
	void release() override {}
	void stop() override;
	SourceStats stats() const override { return stats_; }
	const char *name() const override { return name_.c_str(); }
	bool frameSize(int &width, int &height) const override;

	bool isVideo() const { return video_; }
	size_t imageCount() const { return files_.size(); }

private:
	FileSource() = default;
	Status readFrame(int &width, int &height, int timeoutMs); // the next frame into pixels_, rewinding when looping
	Status rewind();

	FileSourceOptions options_;
	std::string name_;
	bool video_ = false;
	std::vector<std::string> files_;
	VideoPipe pipe_;
	ImageDecoder decoder_; // its file buffer is reused frame to frame
	int maxWidth_ = 0, maxHeight_ = 0;
	std::vector<uint8_t> pixels_; // the one frame buffer, allocated by start()

	bool started_ = false;
	size_t nextFile_ = 0;      // images: index of the next file
	bool pipeHasFrames_ = false; // video: at least one frame came since the last rewind
	uint64_t frameId_ = 0;
	std::chrono::steady_clock::time_point paceStart_;
	SourceStats stats_;
};

} // namespace ports
} // namespace calped
