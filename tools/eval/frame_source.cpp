// SPDX-License-Identifier: BSD-2-Clause
#include "frame_source.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "../detect/frame_list.h"
#include "external_tools.h"
#include "text_fields.h"

namespace calped::eval_tool {

namespace {

class FolderSource : public FrameSource
{
public:
	explicit FolderSource(const FrameInput &input) : input_(input) {}

	bool next(RgbImage &image, std::string &error) override
	{
		if (index_ >= input_.files.size())
			return false;
		return detect_tool::decodeImage(input_.files[index_++], image, error);
	}

private:
	const FrameInput &input_;
	size_t index_ = 0;
};

// Reads raw RGB frames from ffmpeg's standard output.
class VideoSource : public FrameSource
{
public:
	VideoSource(const FrameInput &input, FILE *pipe) : input_(input), pipe_(pipe) {}
	~VideoSource() override
	{
		if (pipe_)
			pclose(pipe_); // stopped early: ffmpeg's broken pipe is expected
	}

	bool next(RgbImage &image, std::string &error) override
	{
		if (!pipe_ || (input_.maxFrames > 0 && frames_ >= input_.maxFrames))
			return false;
		const size_t bytes = static_cast<size_t>(input_.width) * input_.height * 3;
		image.width = input_.width;
		image.height = input_.height;
		image.pixels.resize(bytes);
		const size_t got = std::fread(image.pixels.data(), 1, bytes, pipe_);
		if (got == bytes) {
			frames_++;
			return true;
		}
		const bool readError = std::ferror(pipe_) != 0;
		const int status = pclose(pipe_);
		pipe_ = nullptr;
		if (readError) {
			error = "cannot read ffmpeg's output for " + input_.video + ": " + std::strerror(errno);
		} else if (status != 0) {
			error = "ffmpeg failed decoding " + input_.video + " (" + describeExitStatus(status) +
				") after " + std::to_string(frames_) + " frames";
		} else if (got != 0) {
			error = "ffmpeg's output for " + input_.video + " ended inside frame " +
				std::to_string(frames_ + 1) + " (" + std::to_string(got) + " of " +
				std::to_string(bytes) + " bytes): is the frame size " +
				std::to_string(input_.width) + "x" + std::to_string(input_.height) + " right?";
		} else if (frames_ == 0) {
			error = "ffmpeg decoded no frames from " + input_.video;
		} else {
			return false; // the end
		}
		return false;
	}

private:
	const FrameInput &input_;
	FILE *pipe_;
	long frames_ = 0;
};

} // namespace

bool parseFrameSize(const std::string &text, int &width, int &height)
{
	const size_t x = text.find('x');
	if (x == std::string::npos)
		return false;
	long w, h;
	if (!parseLong(text.substr(0, x), w) || !parseLong(text.substr(x + 1), h))
		return false;
	if (w < 1 || h < 1 || w > 16384 || h > 16384)
		return false;
	width = static_cast<int>(w);
	height = static_cast<int>(h);
	return true;
}

std::string FrameInput::label(long frame) const
{
	if (isVideo())
		return "frame " + std::to_string(frame) + " of " + video;
	const size_t k = static_cast<size_t>(frame - 1);
	return "frame " + std::to_string(frame) + (k < files.size() ? " (" + files[k] + ")" : "");
}

std::unique_ptr<FrameSource> FrameInput::open(std::string &error) const
{
	if (!isVideo())
		return std::unique_ptr<FrameSource>(new FolderSource(*this));
	// With a frame limit ffmpeg stops by itself rather than on a broken pipe (which it
	// reports, as it ignores SIGPIPE).
	const std::string limit = maxFrames > 0 ? " -frames:v " + std::to_string(maxFrames) : "";
	const std::string cmd = "ffmpeg -nostdin -loglevel error -i " + shellQuote(video) + limit +
				" -f rawvideo -pix_fmt rgb24 -";
	std::fflush(nullptr);
	FILE *pipe = popen(cmd.c_str(), "r");
	if (!pipe) {
		error = "cannot run ffmpeg: " + std::string(std::strerror(errno));
		return nullptr;
	}
	return std::unique_ptr<FrameSource>(new VideoSource(*this, pipe));
}

bool resolveFolderInput(const std::string &dir, long maxFrames, FrameInput &out,
			std::string &error)
{
	out = FrameInput();
	out.maxFrames = maxFrames;
	if (!detect_tool::listFrames({ dir }, out.files, error))
		return false;
	if (maxFrames > 0 && static_cast<size_t>(maxFrames) < out.files.size())
		out.files.resize(static_cast<size_t>(maxFrames));
	// Headers only: an undecodable file fails now, not after minutes of work.
	for (const std::string &path : out.files) {
		int w = 0, h = 0;
		if (!detect_tool::probeImage(path, w, h, error))
			return false;
		out.width = std::max(out.width, w);
		out.height = std::max(out.height, h);
	}
	return true;
}

bool resolveVideoInput(const std::string &path, const std::string &size, long maxFrames,
		       FrameInput &out, std::string &error)
{
	out = FrameInput();
	out.video = path;
	out.maxFrames = maxFrames;
	struct stat st;
	if (stat(path.c_str(), &st) != 0) {
		error = "cannot read video " + path + ": " + std::strerror(errno);
		return false;
	}
	if (!findExecutable("ffmpeg")) {
		error = "--video needs ffmpeg on the PATH (Debian: apt-get install ffmpeg)";
		return false;
	}
	if (!size.empty()) {
		if (!parseFrameSize(size, out.width, out.height)) {
			error = "--size must be WIDTHxHEIGHT, e.g. 768x576, got '" + size + "'";
			return false;
		}
		return true;
	}
	if (!findExecutable("ffprobe")) {
		error = "no ffprobe to read the frame size of " + path + "; give it with --size WxH";
		return false;
	}
	std::string text;
	if (!runCapture("ffprobe -v error -select_streams v:0 -show_entries stream=width,height "
			"-of csv=p=0:s=x " + shellQuote(path),
			text, error)) {
		error = "cannot read the frame size of " + path + ": " + error;
		return false;
	}
	while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == 'x'))
		text.pop_back();
	if (!parseFrameSize(text, out.width, out.height)) {
		error = "ffprobe gave no frame size for " + path + " ('" + text + "'); give it with --size WxH";
		return false;
	}
	return true;
}

} // namespace calped::eval_tool
