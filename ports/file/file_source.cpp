// SPDX-License-Identifier: BSD-2-Clause
#include "file_source.h"

#include <new>
#include <thread>

namespace calped {
namespace ports {

Status FileSource::open(const FileSourceOptions &options, std::unique_ptr<FileSource> &out)
{
	if (!(options.fps >= 0) || options.fps > 1000)
		return Status::error(ErrorCode::InvalidArgument,
				     "file source: fps must be 0 (as fast as possible) or in (0, 1000], got %g",
				     options.fps);
	if (options.maxFrames < 0)
		return Status::error(ErrorCode::InvalidArgument,
				     "file source: maxFrames must be >= 0, got %ld", options.maxFrames);
	std::unique_ptr<FileSource> src(new (std::nothrow) FileSource());
	if (!src)
		return Status::error(ErrorCode::OutOfMemory, "file source: out of memory");
	src->options_ = options;
	src->video_ = isVideoFileName(options.path);
	Status st;
	if (src->video_) {
		st = probeVideo(options.path, src->maxWidth_, src->maxHeight_);
		src->name_ = "file:" + options.path + " (video)";
	} else {
		st = listImageFiles(options.path, src->files_);
		if (st.ok())
			st = probeImageFiles(src->decoder_, src->files_, src->maxWidth_, src->maxHeight_);
		src->name_ = "file:" + options.path + " (" + std::to_string(src->files_.size()) +
			     (src->files_.size() == 1 ? " image)" : " images)");
	}
	if (!st.ok())
		return st;
	out = std::move(src);
	return Status::success();
}

FileSource::~FileSource()
{
	stop();
}

bool FileSource::frameSize(int &width, int &height) const
{
	width = maxWidth_;
	height = maxHeight_;
	return true;
}

Status FileSource::start()
{
	stop();
	try {
		pixels_.assign(static_cast<size_t>(maxWidth_) * maxHeight_ * 3, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: no memory for a %dx%d frame",
				     name_.c_str(), maxWidth_, maxHeight_);
	}
	stats_ = SourceStats();
	frameId_ = 0;
	nextFile_ = 0;
	started_ = true;
	paceStart_ = std::chrono::steady_clock::now();
	return rewind();
}

Status FileSource::rewind()
{
	nextFile_ = 0;
	pipeHasFrames_ = false;
	if (video_)
		return pipe_.open(options_.path, maxWidth_, maxHeight_);
	return Status::success();
}

Status FileSource::readFrame(int &width, int &height, int timeoutMs)
{
	// At most one rewind per call: an empty video must end, not spin.
	for (int attempt = 0; attempt < 2; attempt++) {
		if (video_) {
			const Status st = pipe_.read(pixels_.data(), timeoutMs);
			if (st.code() == ErrorCode::Timeout)
				stats_.timeouts++;
			if (st.ok()) {
				pipeHasFrames_ = true;
				width = maxWidth_;
				height = maxHeight_;
				return st;
			}
			if (st.code() != ErrorCode::EndOfStream)
				return st;
			if (!pipeHasFrames_)
				return Status::error(ErrorCode::IoError, "%s has no video frames",
						     options_.path.c_str());
		} else if (nextFile_ < files_.size()) {
			return decodeImageInto(decoder_, files_[nextFile_++], pixels_.data(), pixels_.size(), width,
					       height);
		}
		if (!options_.loop)
			return Status::error(ErrorCode::EndOfStream, "%s: no more frames", name_.c_str());
		const Status st = rewind();
		if (!st.ok())
			return st;
	}
	return Status::error(ErrorCode::EndOfStream, "%s: no more frames", name_.c_str());
}

Status FileSource::next(Frame &frame, int timeoutMs)
{
	if (!started_)
		return Status::error(ErrorCode::InvalidArgument, "%s: next() before start()", name_.c_str());
	if (options_.maxFrames > 0 && frameId_ >= static_cast<uint64_t>(options_.maxFrames))
		return Status::error(ErrorCode::EndOfStream, "%s: %ld frames played", name_.c_str(),
				     options_.maxFrames);

	using namespace std::chrono;
	if (options_.fps > 0) {
		// Frame k is due k / fps after start(): a slow consumer catches up, never bursts past.
		const auto due = paceStart_ + duration_cast<steady_clock::duration>(
						      duration<double>(static_cast<double>(frameId_) / options_.fps));
		const auto now = steady_clock::now();
		if (due - now > milliseconds(timeoutMs)) {
			std::this_thread::sleep_for(milliseconds(timeoutMs));
			stats_.timeouts++;
			return Status::error(ErrorCode::Timeout, "%s: no frame within %d ms", name_.c_str(),
					     timeoutMs);
		}
		std::this_thread::sleep_until(due);
	}

	int width = 0, height = 0;
	const Status st = readFrame(width, height, timeoutMs);
	if (!st.ok())
		return st;
	frameId_++;
	stats_.delivered++;
	frame.image = ImageView::rgb8(pixels_.data(), width, height);
	frame.id = frameId_;
	frame.timestampNs = duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
	return Status::success();
}

void FileSource::stop()
{
	pipe_.close();
	started_ = false;
}

} // namespace ports
} // namespace calped
