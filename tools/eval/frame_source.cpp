// SPDX-License-Identifier: BSD-2-Clause
#include "frame_source.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "args.h"
#include "frame_list.h"
#include "stop_signal.h"
#include "video_pipe.h"
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
		return decoder_.decode(input_.files[index_++], image, error);
	}

private:
	const FrameInput &input_;
	ports::ImageDecoder decoder_;
	size_t index_ = 0;
};

// Raw RGB frames from the file port's ffmpeg pipe.
class VideoSource : public FrameSource
{
public:
	explicit VideoSource(const FrameInput &input) : input_(input) {}

	bool open(std::string &error)
	{
		const Status st = pipe_.open(input_.video, input_.width, input_.height);
		if (!st.ok())
			error = st.message();
		return st.ok();
	}

	bool next(RgbImage &image, std::string &error) override
	{
		if (input_.maxFrames > 0 && frames_ >= input_.maxFrames)
			return false;
		image.width = input_.width;
		image.height = input_.height;
		image.pixels.resize(static_cast<size_t>(input_.width) * input_.height * 3);
		// Short waits, so that a stop signal is seen however slow ffmpeg is.
		Status st;
		do
			st = pipe_.read(image.pixels.data(), 200);
		while (st.code() == ErrorCode::Timeout && !apps::stopRequested());
		if (st.ok()) {
			frames_++;
			return true;
		}
		if (st.code() == ErrorCode::Timeout)
			return false; // stopped: runMethod() reports it
		if (st.code() != ErrorCode::EndOfStream)
			error = st.message();
		else if (frames_ == 0)
			error = "ffmpeg decoded no frames from " + input_.video;
		return false;
	}

private:
	const FrameInput &input_;
	ports::VideoPipe pipe_;
	long frames_ = 0;
};

} // namespace

std::string FrameInput::label(long frame) const
{
	if (isVideo())
		return "frame " + std::to_string(frame) + " of " + video;
	const size_t k = static_cast<size_t>(frame - 1);
	return "frame " + std::to_string(frame) + (k < files.size() ? " (" + files[k] + ")" : "");
}

std::string FrameInput::file(long frame) const
{
	const size_t k = static_cast<size_t>(frame - 1);
	return isVideo() ? video : k < files.size() ? files[k] : std::string();
}

std::unique_ptr<FrameSource> FrameInput::open(std::string &error) const
{
	if (!isVideo())
		return std::unique_ptr<FrameSource>(new FolderSource(*this));
	std::unique_ptr<VideoSource> source(new VideoSource(*this));
	if (!source->open(error))
		return nullptr;
	return source;
}

bool resolveFolderInput(const std::string &dir, long maxFrames, FrameInput &out,
			std::string &error)
{
	out = FrameInput();
	out.maxFrames = maxFrames;
	if (!apps::listFrames({ dir }, out.files, error))
		return false;
	if (maxFrames > 0 && static_cast<size_t>(maxFrames) < out.files.size())
		out.files.resize(static_cast<size_t>(maxFrames));
	// Headers only: an undecodable file fails now, not after minutes of work.
	ports::ImageDecoder decoder;
	for (const std::string &path : out.files) {
		int w = 0, h = 0;
		if (!decoder.probe(path, w, h, error))
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
		if (!apps::parseFrameSize(size, out.width, out.height)) {
			error = "--size must be WIDTHxHEIGHT, e.g. 768x576, got '" + size + "'";
			return false;
		}
		return true;
	}
	const Status probed = ports::probeVideo(path, out.width, out.height);
	if (!probed.ok()) {
		error = std::string(probed.message()) + "; or give the frame size with --size WxH";
		return false;
	}
	return true;
}

} // namespace calped::eval_tool
