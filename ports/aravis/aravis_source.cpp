// SPDX-License-Identifier: BSD-2-Clause
#include "aravis_source.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>
#include <thread>

#include <arv.h>

#include "gvcp_probe.h"
#include "pixel_formats.h"
#include "socket_presize.h"

namespace calped {
namespace ports {

namespace {

// Aravis's named stream counter, 0 when this kind of stream has none (the Fake stream).
uint64_t streamInfo(ArvStream *stream, const char *name)
{
	const guint n = arv_stream_get_n_infos(stream);
	for (guint i = 0; i < n; i++) {
		const char *info = arv_stream_get_info_name(stream, i);
		if (info && std::strcmp(info, name) == 0 && arv_stream_get_info_type(stream, i) == G_TYPE_UINT64)
			return arv_stream_get_info_uint64(stream, i);
	}
	return 0;
}

// The UDP receive buffer: as asked, or four payloads (each 1400-byte packet costs the
// kernel about 2.3 KB on loopback, and a second frame may start before the first is read).
gint socketBufferBytes(const AravisOptions &o, size_t payload)
{
	if (o.socketBufferBytes > 0)
		return o.socketBufferBytes;
	const size_t bytes = std::min<size_t>(std::max<size_t>(4 * payload, 1u << 20), 64u << 20);
	return static_cast<gint>(bytes);
}

// Copies a GError's message into a Status and frees it.
Status fromGError(ErrorCode code, GError *&error, const char *what, const std::string &camera)
{
	const Status st = Status::error(code, "camera %s: %s: %s", camera.c_str(), what,
					error ? error->message : "unknown error");
	g_clear_error(&error);
	return st;
}

std::string describe(const AravisOptions &o)
{
	return o.camera.empty() ? std::string("(first found)") : "'" + o.camera + "'";
}

// A stream counter since acquisition started (0 when the stream never started).
uint64_t streamCounterSinceStart(uint64_t now, uint64_t atStart)
{
	return now >= atStart ? now - atStart : 0;
}

// Pops wait at most this long at a time, so a heartbeat loss is seen within it.
constexpr int kPollMs = 100;

} // namespace

Status AravisSource::open(const AravisOptions &options, std::unique_ptr<AravisSource> &out)
{
	if (options.buffers < 2 || options.buffers > kMaxBuffers)
		return Status::error(ErrorCode::InvalidArgument,
				     "aravis: buffers must be 2..%d, got %d", kMaxBuffers, options.buffers);
	if (options.width < 0 || options.height < 0 || !(options.frameRate >= 0) ||
	    options.packetSize < 0 || options.socketBufferBytes < 0 || options.packetTimeoutMs < 0 ||
	    options.frameRetentionMs < 0 || options.lostAfterMs < 1 || options.reconnectEveryMs < 1)
		return Status::error(ErrorCode::InvalidArgument,
				     "aravis: sizes, rates, packet settings and timeouts must be >= 0 "
				     "(lostAfterMs and reconnectEveryMs >= 1)");
	std::unique_ptr<AravisSource> src(new (std::nothrow) AravisSource());
	if (!src)
		return Status::error(ErrorCode::OutOfMemory, "aravis: out of memory");
	src->options_ = options;
	src->name_ = "aravis:" + (options.camera.empty() ? std::string("first camera") : options.camera);
	const Status st = src->connect();
	if (!st.ok())
		return st;
	out = std::move(src);
	return Status::success();
}

AravisSource::~AravisSource()
{
	stop();
}

Status AravisSource::connect()
{
	GError *error = nullptr;
	const std::string who = describe(options_);
	camera_ = arv_camera_new(options_.camera.empty() ? nullptr : options_.camera.c_str(), &error);
	if (!camera_) {
		const Status st = Status::error(ErrorCode::CameraNotFound, "no camera %s: %s", who.c_str(),
						error ? error->message : "none found");
		g_clear_error(&error);
		return st;
	}
	Status st;
	// What the camera had before this run changed it: a refused or unusable setting is
	// put back, so it never sticks into the next run (a camera keeps what it was told).
	GError *readError = nullptr;
	const ArvPixelFormat originalFormat = arv_camera_get_pixel_format(camera_, &readError);
	gint originalRegion[4] = { 0, 0, 0, 0 };
	if (!readError)
		arv_camera_get_region(camera_, &originalRegion[0], &originalRegion[1], &originalRegion[2],
				      &originalRegion[3], &readError);
	const bool canRestore = readError == nullptr;
	g_clear_error(&readError);
	auto restore = [&] {
		if (!canRestore || !camera_)
			return;
		GError *e = nullptr;
		arv_camera_set_pixel_format(camera_, originalFormat, &e);
		g_clear_error(&e);
		arv_camera_set_region(camera_, originalRegion[0], originalRegion[1], originalRegion[2],
				      originalRegion[3], &e);
		g_clear_error(&e);
	};
	auto fail = [&](ErrorCode code, const char *what) {
		st = fromGError(code, error, what, who);
		restore();
		disconnect();
		return st;
	};

	arv_camera_set_acquisition_mode(camera_, ARV_ACQUISITION_MODE_CONTINUOUS, &error);
	if (error)
		return fail(ErrorCode::CameraError, "cannot select continuous acquisition");
	if (!options_.pixelFormat.empty()) {
		arv_camera_set_pixel_format_from_string(camera_, options_.pixelFormat.c_str(), &error);
		if (error)
			return fail(ErrorCode::CameraError,
				    ("refused pixel format " + options_.pixelFormat).c_str());
	}
	if (options_.width > 0 || options_.height > 0) {
		gint x = 0, y = 0, w = 0, h = 0;
		arv_camera_get_region(camera_, &x, &y, &w, &h, &error);
		if (!error)
			arv_camera_set_region(camera_, x, y, options_.width > 0 ? options_.width : w,
					      options_.height > 0 ? options_.height : h, &error);
		if (error)
			return fail(ErrorCode::CameraError, "refused the region size");
	}
	if (options_.frameRate > 0) {
		arv_camera_set_frame_rate(camera_, options_.frameRate, &error);
		if (error)
			return fail(ErrorCode::CameraError, "refused the frame rate");
	}
	if (arv_camera_is_gv_device(camera_)) {
		if (options_.packetSize > 0) {
			arv_camera_gv_set_packet_size(camera_, options_.packetSize, &error);
			if (error)
				return fail(ErrorCode::CameraError, "refused the packet size");
		}
		arv_camera_gv_set_stream_options(camera_, options_.packetSocket
								  ? ARV_GV_STREAM_OPTION_NONE
								  : ARV_GV_STREAM_OPTION_PACKET_SOCKET_DISABLED);
	}

	// What the camera will actually send.
	const ArvPixelFormat pfnc = arv_camera_get_pixel_format(camera_, &error);
	if (error)
		return fail(ErrorCode::CameraError, "cannot read the pixel format");
	const char *pfName = arv_camera_get_pixel_format_as_string(camera_, nullptr);
	formatName_ = pfName ? pfName : "?";
	AnnouncedStream announced;
	announced.pfnc = pfnc;
	gint x = 0, y = 0, w = 0, h = 0;
	arv_camera_get_region(camera_, &x, &y, &w, &h, &error);
	if (!error)
		announced.payload = arv_camera_get_payload(camera_, &error);
	if (error)
		return fail(ErrorCode::CameraError, "cannot read the region and payload");
	announced.width = w;
	announced.height = h;
	// Checked before a buffer is sized from it: a camera's registers are outside input.
	StreamPlan plan;
	const Status planned = planStream(announced, formatName_.c_str(), plan);
	if (!planned.ok()) {
		st = Status::error(planned.code(), "camera %s: %s", who.c_str(), planned.message());
		restore();
		disconnect();
		return st;
	}
	width_ = plan.width;
	height_ = plan.height;
	payload_ = plan.payload;

	stream_ = arv_camera_create_stream(camera_, nullptr, nullptr, &error);
	if (!stream_)
		return fail(ErrorCode::CameraError, "cannot create the stream");
	if (ARV_IS_GV_STREAM(stream_)) {
		// Aravis applies this when the first frame arrives, too late for that frame when
		// its thread starts late: we size the socket now as well (socket_presize.h).
		const gint socketBytes = socketBufferBytes(options_, payload_);
		g_object_set(stream_, "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_FIXED,
			     "socket-buffer-size", socketBytes, nullptr);
		socketPresized_ = presizeUdpSocket(arv_gv_stream_get_port(ARV_GV_STREAM(stream_)), socketBytes);
		g_object_set(stream_, "packet-resend",
			     options_.packetResend ? ARV_GV_STREAM_PACKET_RESEND_ALWAYS
						   : ARV_GV_STREAM_PACKET_RESEND_NEVER,
			     nullptr);
		if (options_.packetTimeoutMs > 0)
			g_object_set(stream_, "packet-timeout", static_cast<guint>(options_.packetTimeoutMs * 1000),
				     nullptr);
		if (options_.frameRetentionMs > 0)
			g_object_set(stream_, "frame-retention",
				     static_cast<guint>(options_.frameRetentionMs * 1000), nullptr);
	}
	// The fixed pool: every frame lives in one of these until stop(). Aravis gets them at
	// start(): its in-process Fake stream fills every queued buffer from the stream's
	// creation on, and such a frame, made before start(), must not be lent.
	for (pooled_ = 0; pooled_ < options_.buffers; pooled_++)
		pool_[pooled_] = arv_buffer_new_allocate(payload_);
	underrunsAtStart_ = missingFramesAtStart_ = UINT64_MAX; // not started: nothing counts

	if (ARV_IS_GV_DEVICE(arv_camera_get_device(camera_))) {
		GSocketAddress *sa = arv_gv_device_get_device_address(ARV_GV_DEVICE(arv_camera_get_device(camera_)));
		if (sa && G_IS_INET_SOCKET_ADDRESS(sa)) {
			gchar *text = g_inet_address_to_string(
				g_inet_socket_address_get_address(G_INET_SOCKET_ADDRESS(sa)));
			if (text)
				g_strlcpy(deviceAddress_, text, sizeof(deviceAddress_));
			g_free(text);
		}
	}
	numbers_.restart(); // a restarted camera numbers its frames afresh
	controlLost_ = false;
	dead_ = false;
	lostHandler_ = g_signal_connect(arv_camera_get_device(camera_), "control-lost",
					G_CALLBACK(onControlLost), this);

	const char *model = arv_camera_get_model_name(camera_, nullptr);
	const char *serial = arv_camera_get_device_serial_number(camera_, nullptr);
	name_ = "aravis:" + (options_.camera.empty() ? std::string("first camera") : options_.camera) +
		" (" + (model ? model : "?") + " " + (serial ? serial : "?") + ", " + formatName_ + " " +
		std::to_string(width_) + "x" + std::to_string(height_) + ")";
	return Status::success();
}

void AravisSource::onControlLost(ArvDevice *, void *self)
{
	// Aravis's heartbeat thread: only flag it, next() acts on it.
	static_cast<AravisSource *>(self)->controlLost_ = true;
}

Status AravisSource::startAcquisition()
{
	for (int i = 0; i < pooled_; i++)
		arv_stream_push_buffer(stream_, pool_[i]);
	pooled_ = 0;
	underrunsAtStart_ = streamInfo(stream_, "n_underruns");
	missingFramesAtStart_ = streamInfo(stream_, "n_missing_frames");
	GError *error = nullptr;
	arv_camera_start_acquisition(camera_, &error);
	if (error)
		return fromGError(ErrorCode::CameraError, error, "cannot start acquisition",
				  describe(options_));
	acquiring_ = true;
	lastFrame_ = Clock::now();
	return Status::success();
}

Status AravisSource::start()
{
	if (started_)
		return Status::success();
	if (!camera_) {
		const Status st = connect();
		if (!st.ok())
			return st;
	}
	const Status st = startAcquisition();
	if (!st.ok())
		return st;
	started_ = true;
	return st;
}

bool AravisSource::frameSize(int &width, int &height) const
{
	width = width_;
	height = height_;
	return width_ > 0 && height_ > 0;
}

void AravisSource::release()
{
	if (lent_ && stream_)
		arv_stream_push_buffer(stream_, lent_);
	lent_ = nullptr;
}

Status AravisSource::lend(ArvBuffer *buffer, uint64_t number, Frame &frame)
{
	size_t size = 0;
	const uint8_t *data = static_cast<const uint8_t *>(arv_buffer_get_image_data(buffer, &size));
	if (data && size == 0) {
		// Aravis 0.8's in-process Fake stream fills the buffer but reports 0 bytes
		// received: every buffer is ours and holds payload_ bytes (the layout check below
		// still applies).
		size = payload_;
	}
	PixelFormat format;
	gint padX = 0, padY = 0;
	if (data)
		arv_buffer_get_image_padding(buffer, &padX, &padY);
	if (!data || !pixelFormatFromPfnc(arv_buffer_get_image_pixel_format(buffer), format) ||
	    !viewReceivedImage(format, data, size, arv_buffer_get_image_width(buffer),
			       arv_buffer_get_image_height(buffer), padX, frame.image)) {
		// Not an image we can read (a chunk-only payload, a size that does not add up).
		stats_.incomplete++;
		transport_.incompleteOther++;
		arv_stream_push_buffer(stream_, buffer);
		return Status::error(ErrorCode::Timeout, "%s: received a payload that is not a readable image",
				     name_.c_str());
	}
	lent_ = buffer;
	frame.id = number;
	frame.timestampNs = static_cast<int64_t>(arv_buffer_get_system_timestamp(buffer));
	stats_.delivered++;
	lastFrame_ = Clock::now();
	if (transport_.lastReconnectSeconds < 0) // first frame since a restart
		transport_.lastReconnectSeconds = std::chrono::duration<double>(lastFrame_ - lostAt_).count();
	return Status::success();
}

Status AravisSource::next(Frame &frame, int timeoutMs)
{
	release();
	if (!started_)
		return Status::error(ErrorCode::InvalidArgument, "%s: next() before start()", name_.c_str());
	const auto deadline = Clock::now() + std::chrono::milliseconds(std::max(timeoutMs, 0));
	if (reconnecting_ && !tryReconnect(deadline)) {
		stats_.timeouts++;
		return Status::error(ErrorCode::Timeout, "%s: camera lost, reconnecting", name_.c_str());
	}
	if (!camera_)
		return Status::error(ErrorCode::CameraLost, "%s: the camera was lost", name_.c_str());
	ArvBuffer *newest = nullptr;
	uint64_t newestNumber = 0;
	for (;;) {
		if (controlLost_)
			return lost("the camera stopped answering (heartbeat lost)");
		const auto left = std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now());
		if (left.count() <= 0)
			break;
		ArvBuffer *b = arv_stream_timeout_pop_buffer(
			stream_, static_cast<guint64>(std::min<int64_t>(left.count(), kPollMs * 1000)));
		if (!b)
			continue;
		const uint64_t number = numbers_.next(arv_buffer_get_frame_id(b), int64_t(arv_buffer_get_system_timestamp(b)));
		if (arv_buffer_get_status(b) != ARV_BUFFER_STATUS_SUCCESS) {
			const ArvBufferStatus s = arv_buffer_get_status(b);
			stats_.incomplete++;
			(s == ARV_BUFFER_STATUS_MISSING_PACKETS ? transport_.incompleteMissingPackets
			 : s == ARV_BUFFER_STATUS_TIMEOUT       ? transport_.incompleteTimeout
								: transport_.incompleteOther)++;
			arv_stream_push_buffer(stream_, b);
			continue;
		}
		newest = b;
		newestNumber = number;
		// Drop policy: lend the newest complete frame; older ones go back to the pool.
		// Aravis's output queue is in frame order, so the last one out is the newest
		// (and has the highest number).
		while ((b = arv_stream_try_pop_buffer(stream_)) != nullptr) {
			const uint64_t later = numbers_.next(arv_buffer_get_frame_id(b), int64_t(arv_buffer_get_system_timestamp(b)));
			if (arv_buffer_get_status(b) == ARV_BUFFER_STATUS_SUCCESS) {
				arv_stream_push_buffer(stream_, newest);
				stats_.dropped++;
				newest = b;
				newestNumber = later;
			} else {
				stats_.incomplete++;
				transport_.incompleteOther++;
				arv_stream_push_buffer(stream_, b);
			}
		}
		const Status st = lend(newest, newestNumber, frame);
		if (st.ok())
			return st;
	}
	stats_.timeouts++;
	const auto silentMs =
		std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - lastFrame_).count();
	if (silentMs >= options_.lostAfterMs && !cameraAnswers())
		return lost("no frame and no answer from the camera");
	return Status::error(ErrorCode::Timeout, "%s: no frame within %d ms", name_.c_str(), timeoutMs);
}

bool AravisSource::cameraAnswers()
{
	if (controlLost_)
		return false;
	if (deviceAddress_[0]) {
		// GigE Vision: our own quick probe, three tries of 300 ms.
		for (int attempt = 0; attempt < 3; attempt++) {
			const GvcpProbe r = probeGvcp(deviceAddress_, 300);
			if (r != GvcpProbe::Silent)
				return r == GvcpProbe::Answers;
		}
		return false;
	}
	GError *error = nullptr;
	guint32 value = 0;
	// Other devices: a register read through Aravis (register 0 exists on all of them).
	arv_device_read_register(arv_camera_get_device(camera_), 0, &value, &error);
	const bool ok = error == nullptr;
	g_clear_error(&error);
	return ok;
}

Status AravisSource::lost(const char *why)
{
	transport_.lostEvents++;
	lostAt_ = Clock::now();
	dead_ = true;
	disconnect();
	if (!options_.reconnect)
		return Status::error(ErrorCode::CameraLost, "%s: camera lost: %s", name_.c_str(), why);
	reconnecting_ = true;
	lastAttempt_ = Clock::time_point();
	stats_.timeouts++;
	return Status::error(ErrorCode::Timeout, "%s: camera lost (%s), reconnecting", name_.c_str(), why);
}

bool AravisSource::tryReconnect(Clock::time_point deadline)
{
	for (;;) {
		const auto now = Clock::now();
		if (now - lastAttempt_ >= std::chrono::milliseconds(options_.reconnectEveryMs)) {
			lastAttempt_ = now;
			// Opening an absent GigE camera takes Aravis seconds of retries; our probe
			// answers at once, so only a camera that answers is opened.
			const bool worthTrying = !deviceAddress_[0] || probeGvcp(deviceAddress_, 200) == GvcpProbe::Answers;
			if (worthTrying && connect().ok()) {
				if (startAcquisition().ok()) {
					reconnecting_ = false;
					stats_.restarts++;
					transport_.lastReconnectSeconds = -1; // set by the first frame
					return true;
				}
				disconnect();
			}
		}
		if (Clock::now() >= deadline)
			return false;
		std::this_thread::sleep_until(
			std::min(deadline, lastAttempt_ + std::chrono::milliseconds(options_.reconnectEveryMs)));
	}
}

void AravisSource::accumulateStreamCounters()
{
	if (!stream_)
		return;
	closedUnderruns_ += streamCounterSinceStart(streamInfo(stream_, "n_underruns"), underrunsAtStart_);
	closedMissingFrames_ +=
		streamCounterSinceStart(streamInfo(stream_, "n_missing_frames"), missingFramesAtStart_);
	if (ARV_IS_GV_STREAM(stream_)) {
		guint64 resent = 0, missing = 0;
		arv_gv_stream_get_statistics(ARV_GV_STREAM(stream_), &resent, &missing);
		closedResent_ += resent;
		closedMissing_ += missing;
	}
}

void AravisSource::disconnect()
{
	release();
	if (camera_ && acquiring_ && !dead_) {
		// A camera known lost is not told to stop: every command would wait for its timeout.
		GError *error = nullptr;
		arv_camera_stop_acquisition(camera_, &error);
		g_clear_error(&error);
	}
	acquiring_ = false;
	accumulateStreamCounters();
	if (camera_ && lostHandler_)
		g_signal_handler_disconnect(arv_camera_get_device(camera_), lostHandler_);
	lostHandler_ = 0;
	if (camera_ && dead_) {
		releaseDeadCamera();
	} else {
		if (stream_)
			g_object_unref(stream_); // joins the receive thread, frees the pool
		if (camera_)
			g_object_unref(camera_);
	}
	stream_ = nullptr;
	camera_ = nullptr;
	for (int i = 0; i < pooled_; i++) // never given to Aravis (not started)
		g_object_unref(pool_[i]);
	pooled_ = 0;
}

void AravisSource::releaseDeadCamera()
{
	// Aravis's stream and device finalizers write to the camera (stream channel reset,
	// control release) and wait out every retry, about 5 s each, when nobody answers: done
	// aside, so CameraLost is reported (and reconnection tried) without that wait. stop()
	// joins it.
	if (reaper_.joinable())
		reaper_.join();
	ArvStream *stream = stream_;
	ArvCamera *camera = camera_;
	stream_ = nullptr;
	camera_ = nullptr;
	auto release = [stream, camera] {
		if (stream)
			g_object_unref(stream); // resets the stream channel: waits out its retries
		g_object_unref(camera);         // gives up control: the same
	};
	try {
		reaper_ = std::thread(release);
	} catch (...) {
		release();
	}
}

void AravisSource::stop()
{
	disconnect();
	if (reaper_.joinable())
		reaper_.join();
	started_ = false;
	reconnecting_ = false;
}

SourceStats AravisSource::stats() const
{
	SourceStats s = stats_;
	// A frame the consumer never got because no buffer was free, or that never arrived
	// at all: counted with the drops (Aravis's own underrun counter counts packets, not
	// frames, so it is reported apart).
	s.dropped += numbers_.unseen();
	return s;
}

AravisStats AravisSource::transportStats() const
{
	AravisStats t = transport_;
	t.unseenFrames = numbers_.unseen();
	t.lostAcrossReconnects = numbers_.lostAcrossRestarts();
	t.underruns = closedUnderruns_;
	t.missingFrames = closedMissingFrames_;
	t.resentPackets = closedResent_;
	t.missingPackets = closedMissing_;
	if (stream_) {
		t.underruns += streamCounterSinceStart(streamInfo(stream_, "n_underruns"), underrunsAtStart_);
		t.missingFrames +=
			streamCounterSinceStart(streamInfo(stream_, "n_missing_frames"), missingFramesAtStart_);
		if (ARV_IS_GV_STREAM(stream_)) {
			guint64 resent = 0, missing = 0;
			arv_gv_stream_get_statistics(ARV_GV_STREAM(stream_), &resent, &missing);
			t.resentPackets += resent;
			t.missingPackets += missing;
		}
	}
	if (t.lastReconnectSeconds < 0)
		t.lastReconnectSeconds = 0;
	return t;
}

} // namespace ports
} // namespace calped
