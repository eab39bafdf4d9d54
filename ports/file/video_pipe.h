// SPDX-License-Identifier: BSD-2-Clause
// The video half of the file source: ffmpeg decodes the file to raw RGB8 on a pipe
// (`ffmpeg -loglevel error -i FILE -f rawvideo -pix_fmt rgb24 -`), read one fixed-size
// frame at a time into a caller-owned buffer. ffprobe gives the size first. ffmpeg's stderr is
// drained while frames are read (a child blocked on a full stderr pipe would never send its
// next frame); its last bytes are kept for the error message.
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
	// IoError when ffmpeg failed or reported an error (damaged data: its message is
	// included), at once, not after it dropped frames and renumbered the rest. With timeoutMs >= 0, Timeout
	// when no byte came for that long; a signal interrupting the wait also returns Timeout,
	// so the caller can look at its stop flag. After Timeout, call again with the same
	// buffer: the part of the frame already read is kept.
	Status read(uint8_t *pixels, int timeoutMs = -1);
	// Stops ffmpeg (if still running) and closes the pipes; safe to call twice.
	void close();

private:
	Status finish(); // reaps ffmpeg after end of data, turning a failure into IoError
	bool drainErrors(); // reads what ffmpeg wrote on stderr into errorTail_; false at its end
	Status failed(const char *what); // stops ffmpeg: IoError "WHAT PATH: its first line"
	std::string firstErrorLine() const;

	std::string path_;
	size_t frameBytes_ = 0;
	pid_t pid_ = -1;
	int dataFd_ = -1;
	int errorFd_ = -1;
	size_t got_ = 0; // bytes of the current frame read so far
	char errorTail_[512] = {}; // the last bytes ffmpeg wrote on stderr
	size_t errorLength_ = 0;
};

} // namespace ports
} // namespace calped
