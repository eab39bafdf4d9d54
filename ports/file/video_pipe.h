// SPDX-License-Identifier: BSD-2-Clause
// The video half of the file source: ffmpeg decodes the file to raw RGB8 on a pipe
// (`ffmpeg -loglevel error -i FILE -f rawvideo -pix_fmt rgb24 -`), read one fixed-size
// frame at a time into a caller-owned buffer. ffprobe gives the size first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <sys/types.h>

#include <calped/status.h>

namespace calped {
namespace ports {

// True for the extensions treated as video (.avi .mp4 .mkv .mov .webm .mpg .mpeg .m4v .y4m).
bool isVideoFileName(const std::string &path);

// Frame size of the first video stream. IoError when ffprobe is missing or the file has
// no decodable video.
Status probeVideo(const std::string &path, int &width, int &height);

class VideoPipe
{
public:
	VideoPipe() = default;
	~VideoPipe() { close(); }
	VideoPipe(const VideoPipe &) = delete;
	VideoPipe &operator=(const VideoPipe &) = delete;

	// Starts ffmpeg on `path`; frames are width x height RGB8.
	Status open(const std::string &path, int width, int height);
	// Reads the next frame (3 * width * height bytes). EndOfStream after the last frame;
	// IoError when ffmpeg failed (its message is included).
	Status read(uint8_t *pixels);
	// Stops ffmpeg (if still running) and closes the pipes; safe to call twice.
	void close();

private:
	Status finish(); // reaps ffmpeg after end of data, turning a failure into IoError

	std::string path_;
	size_t frameBytes_ = 0;
	pid_t pid_ = -1;
	int dataFd_ = -1;
	int errorFd_ = -1;
};

} // namespace ports
} // namespace calped
