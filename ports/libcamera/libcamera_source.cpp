// SPDX-License-Identifier: BSD-2-Clause
#include "libcamera_source.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include <libcamera/camera.h>
#include <libcamera/camera_manager.h>
#include <libcamera/control_ids.h>
#include <libcamera/controls.h>
#include <libcamera/framebuffer.h>
#include <libcamera/framebuffer_allocator.h>
#include <libcamera/request.h>
#include <libcamera/stream.h>

#include "camera_lookup.h"
#include "format_map.h"
#include "frame_queue.h"
#include "plane_mapping.h"

namespace calped {
namespace ports {

namespace {

// After this many failed or cancelled frames in a row the camera counts as lost: a broken
// pipeline would otherwise have its requests cancelled and requeued forever.
constexpr int kMaxFailuresInARow = 64;

// The stream role whose defaults suit a format (raw sensor data, display RGB, video YUV).
libcamera::StreamRole roleFor(PixelFormat format)
{
	switch (format) {
	case PixelFormat::BayerRGGB8:
	case PixelFormat::BayerGRBG8:
	case PixelFormat::BayerGBRG8:
	case PixelFormat::BayerBGGR8:
		return libcamera::StreamRole::Raw;
	case PixelFormat::RGB8:
	case PixelFormat::BGR8:
		return libcamera::StreamRole::Viewfinder;
	default:
		return libcamera::StreamRole::VideoRecording;
	}
}

class LibcameraSource final : public FrameSource
{
public:
	~LibcameraSource() override;

	Status open(const LibcameraOptions &options);

	Status start() override;
	Status next(Frame &frame, int timeoutMs) override;
	void release() override;
	void stop() override;
	SourceStats stats() const override { return queue_.stats(); }
	const char *name() const override { return name_; }
	bool frameSize(int &width, int &height) const override
	{
		width = views_.empty() ? 0 : views_[0].width;
		height = views_.empty() ? 0 : views_[0].height;
		return !views_.empty();
	}

private:
	Status configure(const LibcameraOptions &options);
	Status frameRateControls(double fps);
	Status allocateAndMap();

	// libcamera's thread.
	void onRequestCompleted(libcamera::Request *request);
	void onDisconnected();
	// Either thread: hands a slot's request back to the camera.
	void requeue(int slot);

	std::shared_ptr<libcamera::CameraManager> manager_;
	std::shared_ptr<libcamera::Camera> camera_;
	bool acquired_ = false;
	bool connected_ = false;
	std::unique_ptr<libcamera::CameraConfiguration> config_;
	libcamera::Stream *stream_ = nullptr;
	std::unique_ptr<libcamera::ControlList> startControls_;
	std::unique_ptr<libcamera::FrameBufferAllocator> allocator_;
	std::vector<BufferMapping> mappings_;
	std::vector<ImageView> views_;
	std::vector<std::unique_ptr<libcamera::Request>> requests_;

	FrameQueue queue_;
	bool streaming_ = false;
	int lostAfterMs_ = 0;
	std::chrono::steady_clock::time_point lastFrame_;
	std::atomic<bool> disconnected_{ false };
	char id_[128] = "";
	char name_[256] = "libcamera";
};

Status LibcameraSource::open(const LibcameraOptions &options)
{
	if (options.buffers < 2 || options.buffers > 16)
		return Status::error(ErrorCode::InvalidArgument,
				     "libcamera buffer count must be 2..16, got %d", options.buffers);
	if (options.width < 0 || options.height < 0 || (options.width == 0) != (options.height == 0))
		return Status::error(ErrorCode::InvalidArgument,
				     "libcamera frame size %dx%d: give both width and height, or neither",
				     options.width, options.height);
	if (options.lostAfterMs < 0)
		return Status::error(ErrorCode::InvalidArgument,
				     "libcamera lost-after time must be >= 0 ms, got %d",
				     options.lostAfterMs);
	lostAfterMs_ = options.lostAfterMs;
	if (!(options.fps >= 0 && options.fps <= 1000))
		return Status::error(ErrorCode::InvalidArgument,
				     "libcamera frame rate must be 0 (camera default) to 1000, got %g",
				     options.fps);

	Status st = sharedCameraManager(options.quietLibcameraLog, manager_);
	if (!st.ok())
		return st;
	if (!(st = findCamera(*manager_, options.camera, camera_)).ok())
		return st;
	std::snprintf(id_, sizeof(id_), "%s", camera_->id().c_str());

	int ret = camera_->acquire();
	if (ret < 0)
		return Status::error(ErrorCode::CameraError, "camera '%s' cannot be acquired: %s%s",
				     id_, std::strerror(-ret),
				     ret == -EBUSY ? " (in use by another program or source)" : "");
	acquired_ = true;

	if (!(st = configure(options)).ok() || !(st = frameRateControls(options.fps)).ok() ||
	    !(st = allocateAndMap()).ok())
		return st;

	camera_->requestCompleted.connect(this, &LibcameraSource::onRequestCompleted);
	camera_->disconnected.connect(this, &LibcameraSource::onDisconnected);
	connected_ = true;
	return Status::success();
}

// "NV12, YUYV, MJPEG": what a stream configuration offers, for error messages.
std::string offeredFormats(const libcamera::StreamConfiguration &cfg)
{
	std::string offered;
	for (const libcamera::PixelFormat &f : cfg.formats().pixelformats())
		offered += (offered.empty() ? "" : ", ") + f.toString();
	return offered.empty() ? "nothing" : offered;
}

// Without a requested format: the first of these the camera offers.
const PixelFormat kPreferredFormats[] = { PixelFormat::NV12, PixelFormat::YUV420,
					  PixelFormat::YUYV, PixelFormat::BGR8,
					  PixelFormat::RGB8, PixelFormat::Gray8 };

Status LibcameraSource::configure(const LibcameraOptions &options)
{
	libcamera::PixelFormat wanted;
	if (options.format && !libcameraFormatFor(*options.format, wanted))
		return Status::error(ErrorCode::InvalidArgument,
				     "libcamera has no pixel format for calped's %s",
				     pixelFormatName(*options.format));

	// A named vector: libcamera 0.0.3 takes StreamRoles, later versions a Span of roles.
	const libcamera::StreamRoles roles = {
		roleFor(options.format.value_or(PixelFormat::NV12))
	};
	config_ = camera_->generateConfiguration(roles);
	if (!config_ || config_->empty())
		return Status::error(ErrorCode::CameraError,
				     "camera '%s' has no stream configuration for %s", id_,
				     options.format ? pixelFormatName(*options.format) : "video");
	libcamera::StreamConfiguration &cfg = config_->at(0);
	if (!options.format) {
		const std::vector<libcamera::PixelFormat> offered = cfg.formats().pixelformats();
		for (PixelFormat f : kPreferredFormats) {
			libcamera::PixelFormat candidate;
			libcameraFormatFor(f, candidate);
			bool found = false;
			for (const libcamera::PixelFormat &o : offered)
				found = found || o == candidate;
			if (found) {
				wanted = candidate;
				break;
			}
		}
		if (!wanted.isValid())
			return Status::error(ErrorCode::CameraError,
					     "camera '%s' offers none of the formats calped reads (it "
					     "offers %s)",
					     id_, offeredFormats(cfg).c_str());
	}
	cfg.pixelFormat = wanted;
	if (options.width > 0)
		cfg.size = libcamera::Size(options.width, options.height);
	cfg.bufferCount = options.buffers;

	if (config_->validate() == libcamera::CameraConfiguration::Invalid)
		return Status::error(ErrorCode::CameraError,
				     "camera '%s' rejects the configuration %s", id_,
				     cfg.toString().c_str());
	if (cfg.pixelFormat != wanted)
		return Status::error(ErrorCode::CameraError,
				     "camera '%s' cannot deliver %s; it offers %s", id_,
				     wanted.toString().c_str(), offeredFormats(cfg).c_str());
	int ret = camera_->configure(config_.get());
	if (ret < 0)
		return Status::error(ErrorCode::CameraError, "camera '%s' refused %s: %s", id_,
				     cfg.toString().c_str(), std::strerror(-ret));
	stream_ = cfg.stream();

	char asked[48] = "";
	if (options.width > 0 && (int(cfg.size.width) != options.width ||
				  int(cfg.size.height) != options.height))
		std::snprintf(asked, sizeof(asked), " (asked %dx%d)", options.width, options.height);
	std::snprintf(name_, sizeof(name_), "libcamera:%s %s %ux%u%s stride %u, %u buffers", id_,
		      wanted.toString().c_str(), cfg.size.width, cfg.size.height, asked, cfg.stride,
		      cfg.bufferCount);
	return Status::success();
}

// A rate is a fixed frame duration: FrameDurationLimits = {d, d} microseconds.
Status LibcameraSource::frameRateControls(double fps)
{
	if (fps <= 0)
		return Status::success();
	const libcamera::ControlInfoMap &controls = camera_->controls();
	auto info = controls.find(&libcamera::controls::FrameDurationLimits);
	if (info == controls.end())
		return Status::error(ErrorCode::CameraError,
				     "camera '%s' has no FrameDurationLimits control: its frame rate "
				     "cannot be set (leave the rate at the camera's default)",
				     id_);
	int64_t duration = static_cast<int64_t>(1e6 / fps + 0.5);
	const libcamera::ControlValue &min = info->second.min();
	const libcamera::ControlValue &max = info->second.max();
	if (min.type() == libcamera::ControlTypeInteger64 && !min.isArray() &&
	    max.type() == libcamera::ControlTypeInteger64 && !max.isArray()) {
		int64_t lo = min.get<int64_t>(), hi = max.get<int64_t>();
		if (duration < lo || (hi > 0 && duration > hi))
			return Status::error(ErrorCode::CameraError,
					     "camera '%s' cannot run at %g fps: frame durations %lld..%lld us "
					     "(%g..%g fps)",
					     id_, fps, static_cast<long long>(lo), static_cast<long long>(hi),
					     hi > 0 ? 1e6 / double(hi) : 0.0, lo > 0 ? 1e6 / double(lo) : 0.0);
	}
	startControls_ = std::make_unique<libcamera::ControlList>(controls);
	int64_t limits[2] = { duration, duration };
	startControls_->set(libcamera::controls::FrameDurationLimits,
			    libcamera::Span<const int64_t, 2>(limits));
	return Status::success();
}

// A fixed pool: every buffer is mapped and described as an ImageView once, here.
Status LibcameraSource::allocateAndMap()
{
	allocator_ = std::make_unique<libcamera::FrameBufferAllocator>(camera_);
	int ret = allocator_->allocate(stream_);
	if (ret < 0)
		return Status::error(ErrorCode::CameraError,
				     "camera '%s': allocating frame buffers failed: %s", id_,
				     std::strerror(-ret));
	const auto &buffers = allocator_->buffers(stream_);
	if (buffers.empty())
		return Status::error(ErrorCode::CameraError, "camera '%s' allocated no frame buffers",
				     id_);

	const libcamera::StreamConfiguration &cfg = config_->at(0);
	const YuvEncoding encoding = yuvEncodingFor(cfg.colorSpace);
	mappings_.resize(buffers.size());
	views_.resize(buffers.size());
	requests_.reserve(buffers.size());
	for (size_t i = 0; i < buffers.size(); ++i) {
		const libcamera::FrameBuffer &buffer = *buffers[i];
		PlaneDesc planes[BufferMapping::kMaxPlanes];
		int count = static_cast<int>(buffer.planes().size());
		if (count > BufferMapping::kMaxPlanes)
			return Status::error(ErrorCode::CameraError,
					     "camera '%s': buffer %zu has %d planes", id_, i, count);
		for (int p = 0; p < count; ++p) {
			const libcamera::FrameBuffer::Plane &plane = buffer.planes()[p];
			if (plane.offset == libcamera::FrameBuffer::Plane::kInvalidOffset)
				return Status::error(ErrorCode::CameraError,
						     "camera '%s': buffer %zu plane %d has no offset", id_,
						     i, p);
			planes[p] = PlaneDesc{ plane.fd.get(), plane.offset, plane.length };
		}
		char what[200];
		std::snprintf(what, sizeof(what), "camera '%s' buffer %zu", id_, i);
		Status st = mappings_[i].map(planes, count, what);
		if (!st.ok())
			return st;
		st = frameView(cfg.pixelFormat, cfg.size.width, cfg.size.height, cfg.stride,
			       mappings_[i].planes(), count, encoding, views_[i]);
		if (!st.ok())
			return st;

		std::unique_ptr<libcamera::Request> request = camera_->createRequest(i);
		if (!request)
			return Status::error(ErrorCode::CameraError,
					     "camera '%s' could not create request %zu", id_, i);
		ret = request->addBuffer(stream_, buffers[i].get());
		if (ret < 0)
			return Status::error(ErrorCode::CameraError,
					     "camera '%s': adding buffer %zu to its request failed: %s",
					     id_, i, std::strerror(-ret));
		requests_.push_back(std::move(request));
	}
	return Status::success();
}

Status LibcameraSource::start()
{
	if (streaming_)
		return Status::success();
	if (disconnected_)
		return Status::error(ErrorCode::CameraLost, "camera '%s' was disconnected", id_);
	char label[160];
	std::snprintf(label, sizeof(label), "camera '%s'", id_);
	queue_.begin(label, kMaxFailuresInARow);
	int ret = camera_->start(startControls_.get());
	if (ret < 0)
		return Status::error(ret == -ENODEV ? ErrorCode::CameraLost : ErrorCode::CameraError,
				     "camera '%s' failed to start: %s", id_, std::strerror(-ret));
	streaming_ = true;
	lastFrame_ = std::chrono::steady_clock::now();
	for (auto &request : requests_) {
		request->reuse(libcamera::Request::ReuseBuffers);
		ret = camera_->queueRequest(request.get());
		if (ret < 0) {
			stop();
			return Status::error(ErrorCode::CameraError,
					     "camera '%s' refused a capture request: %s", id_,
					     std::strerror(-ret));
		}
	}
	return Status::success();
}

Status LibcameraSource::next(Frame &frame, int timeoutMs)
{
	if (!streaming_) {
		if (disconnected_)
			return Status::error(ErrorCode::CameraLost, "camera '%s' was disconnected", id_);
		return Status::error(ErrorCode::CameraError, "camera '%s' is not streaming (start() first)",
				     id_);
	}
	release();
	FrameQueue::Taken taken;
	switch (queue_.take(timeoutMs, taken)) {
	case FrameQueue::Wait::Frame:
		frame.image = views_[taken.slot];
		frame.id = taken.sequence;
		frame.timestampNs = taken.timestampNs;
		lastFrame_ = std::chrono::steady_clock::now();
		return Status::success();
	case FrameQueue::Wait::Timeout: {
		const long long silentMs = std::chrono::duration_cast<std::chrono::milliseconds>(
						   std::chrono::steady_clock::now() - lastFrame_)
						   .count();
		if (lostAfterMs_ > 0 && silentMs >= lostAfterMs_)
			return Status::error(ErrorCode::CameraLost,
					     "camera '%s' sent no complete frame for %lld ms (limit %d ms)",
					     id_, silentMs, lostAfterMs_);
		return Status::error(ErrorCode::Timeout, "camera '%s' sent no frame in %d ms", id_,
				     timeoutMs);
	}
	case FrameQueue::Wait::Lost:
		return queue_.lostStatus();
	case FrameQueue::Wait::Halted:
		break;
	}
	return Status::error(ErrorCode::CameraError, "camera '%s' was stopped", id_);
}

void LibcameraSource::release()
{
	int slot = queue_.giveBack();
	if (slot >= 0)
		requeue(slot);
}

void LibcameraSource::requeue(int slot)
{
	libcamera::Request *request = requests_[slot].get();
	request->reuse(libcamera::Request::ReuseBuffers);
	int ret = camera_->queueRequest(request);
	if (ret < 0) {
		// While stop() runs the camera refuses requests (EACCES): the queue is halted and
		// ignores this.
		char why[200];
		std::snprintf(why, sizeof(why), "camera '%s' %s", id_,
			      ret == -ENODEV ? "was disconnected" : "refused a capture request");
		queue_.lost(ret == -ENODEV ? ErrorCode::CameraLost : ErrorCode::CameraError, why);
	}
}

void LibcameraSource::onRequestCompleted(libcamera::Request *request)
{
	const int slot = static_cast<int>(request->cookie());
	const libcamera::FrameBuffer *buffer = request->findBuffer(stream_);
	const libcamera::FrameMetadata::Status status =
		request->status() == libcamera::Request::RequestCancelled || !buffer
			? libcamera::FrameMetadata::FrameCancelled
			: buffer->metadata().status;
	int requeueSlot = -1;
	if (status == libcamera::FrameMetadata::FrameSuccess)
		requeueSlot = queue_.completed(slot, buffer->metadata().sequence,
					       static_cast<int64_t>(buffer->metadata().timestamp));
	else if (status == libcamera::FrameMetadata::FrameError)
		requeueSlot = queue_.failed(slot, buffer->metadata().sequence);
	else
		requeueSlot = queue_.cancelled(slot);
	if (requeueSlot >= 0)
		requeue(requeueSlot);
}

void LibcameraSource::onDisconnected()
{
	disconnected_ = true;
	char why[200];
	std::snprintf(why, sizeof(why), "camera '%s' was disconnected", id_);
	queue_.lost(ErrorCode::CameraLost, why);
}

void LibcameraSource::stop()
{
	if (!streaming_)
		return;
	// From here completions are ignored: camera_->stop() cancels every queued request and
	// returns once they have all completed (on libcamera's thread).
	queue_.halt();
	camera_->stop();
	streaming_ = false;
}

LibcameraSource::~LibcameraSource()
{
	stop();
	if (connected_) {
		camera_->requestCompleted.disconnect(this);
		camera_->disconnected.disconnect(this);
	}
	if (disconnected_) {
		// libcamera 0.0.3 does not complete the requests pending at a disconnect (a \todo
		// in Camera::disconnect()), so it may still hold them: leave them and their
		// buffers allocated (a few hundred bytes per buffer, once) rather than free memory
		// libcamera could touch.
		for (auto &request : requests_)
			(void)request.release();
		(void)allocator_.release();
	}
	requests_.clear();
	mappings_.clear();
	views_.clear();
	if (allocator_ && stream_)
		allocator_->free(stream_);
	allocator_.reset();
	if (acquired_)
		camera_->release();
	config_.reset();
	camera_.reset();
	manager_.reset();
}

} // namespace

Status openLibcameraSource(const LibcameraOptions &options, std::unique_ptr<FrameSource> &out)
{
	std::unique_ptr<LibcameraSource> source(new LibcameraSource());
	Status st = source->open(options);
	if (!st.ok())
		return st;
	out = std::move(source);
	return Status::success();
}

} // namespace ports
} // namespace calped
