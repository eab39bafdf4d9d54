// SPDX-License-Identifier: BSD-2-Clause
// The Aravis port: a GigE Vision (or any Aravis) camera as a FrameSource. Frames are lent
// straight from Aravis's buffers (no copy) in the camera's native pixel format; a fixed
// pool of buffers is allocated at open. Drop policy, failure handling and the settings
// that stream cleanly are in docs/ports.md.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "frame_numbers.h"
#include "frame_source.h"

// Aravis's GObject types, kept out of this header.
typedef struct _ArvCamera ArvCamera;
typedef struct _ArvStream ArvStream;
typedef struct _ArvBuffer ArvBuffer;
typedef struct _ArvDevice ArvDevice;

namespace calped {
namespace ports {

struct AravisOptions {
	// Aravis device id ("Aravis-Fake-GV01"), an IP address ("127.0.0.1"), or "" for the
	// first camera found.
	std::string camera;
	// GenICam PixelFormat name (Mono8, RGB8, BGR8, YUV422_YUYV_Packed, BayerRG8, ...);
	// "" keeps the camera's current format.
	std::string pixelFormat;
	int width = 0, height = 0; // region size; 0 keeps the camera's
	double frameRate = 0;      // frames per second; 0 keeps the camera's
	int buffers = 4;           // the fixed pool (>= 2: one lent, one filling)

	// GigE Vision transport (ignored for other device kinds). Defaults are the settings
	// that stream cleanly on loopback and on a plain gigabit link (docs/ports.md).
	int packetSize = 0;          // GevSCPSPacketSize in bytes; 0 keeps the camera's
	bool packetSocket = false;   // Aravis's AF_PACKET receive path (root / CAP_NET_RAW only)
	int socketBufferBytes = 0;   // UDP receive buffer; 0: four payloads, 1..64 MiB
	bool packetResend = true;    // ask the camera to resend missing packets
	int packetTimeoutMs = 0;     // wait before asking for a resend; 0 keeps Aravis's (20 ms)
	int frameRetentionMs = 0;    // wait for a frame's last packets; 0 keeps Aravis's (100 ms)

	// Failure handling.
	int lostAfterMs = 2000;       // no frame for this long: check the camera still answers
	bool reconnect = false;       // after a loss, reopen the camera instead of CameraLost
	int reconnectEveryMs = 500;   // pause between reconnection attempts
};

// Transport details beyond SourceStats, for stats lines and the soak.
struct AravisStats {
	uint64_t incompleteMissingPackets = 0; // buffers handed back as MISSING_PACKETS
	uint64_t incompleteTimeout = 0;        // ... as TIMEOUT (frame retention expired)
	uint64_t incompleteOther = 0;          // ... any other failed status
	uint64_t unseenFrames = 0;             // block ids that never came out of Aravis (in dropped)
	uint64_t lostAcrossReconnects = 0;     // of those, frames estimated lost while reconnecting (time away / frame interval)
	uint64_t underruns = 0;                // Aravis's n_underruns since start() (packets without a buffer)
	uint64_t missingFrames = 0;            // Aravis's n_missing_frames since start()
	uint64_t resentPackets = 0;            // packets recovered by resend
	uint64_t missingPackets = 0;           // packets never recovered
	uint64_t lostEvents = 0;               // times the camera was found lost
	double lastReconnectSeconds = 0;       // loss to first frame after the last restart
};

class AravisSource : public FrameSource
{
public:
	// Opens the camera, applies the options and allocates the buffer pool.
	// CameraNotFound (no such device), CameraError (a setting refused, an unsupported
	// pixel format), InvalidArgument (an option out of range).
	static Status open(const AravisOptions &options, std::unique_ptr<AravisSource> &out);
	~AravisSource() override;

	// Gives the buffer pool to Aravis and starts acquisition: only frames made after this
	// are lent (Aravis's in-process Fake stream fills queued buffers even before).
	Status start() override;
	// Lends the newest complete frame (older complete ones are dropped and counted).
	// Incomplete frames are counted and never lent. CameraLost when the camera stopped
	// answering (or, with reconnect, never: Timeout while it is away).
	// Frame::id is the camera's block id unwrapped (frame_numbers.h): it only grows, also
	// across the 16-bit wrap and a reconnection.
	Status next(Frame &frame, int timeoutMs) override;
	void release() override;
	void stop() override;
	SourceStats stats() const override;
	const char *name() const override { return name_.c_str(); }
	bool frameSize(int &width, int &height) const override;

	AravisStats transportStats() const;
	bool connected() const { return camera_ != nullptr; }
	// GigE Vision: whether the stream socket's buffer was sized before acquisition.
	bool socketPresized() const { return socketPresized_; }
	// The device's genicam PixelFormat as a name, e.g. "RGB8".
	const std::string &pixelFormatName() const { return formatName_; }
	// The underlying camera, for settings the options do not cover (and the tests' fake
	// device); null while disconnected. Valid until stop() or a reconnection.
	ArvCamera *arvCamera() const { return camera_; }

private:
	AravisSource() = default;
	Status connect();     // camera, settings, stream, buffers
	Status startAcquisition();
	void disconnect();    // everything connect() made, in reverse; tolerates a dead camera
	void releaseDeadCamera();
	void accumulateStreamCounters();
	bool cameraAnswers();
	Status lost(const char *why); // CameraLost, or start reconnecting
	bool tryReconnect(std::chrono::steady_clock::time_point deadline); // true once streaming again
	Status lend(ArvBuffer *buffer, uint64_t number, Frame &frame);
	static void onControlLost(ArvDevice *device, void *self);

	AravisOptions options_;
	std::string name_;
	std::string formatName_;
	ArvCamera *camera_ = nullptr;
	ArvStream *stream_ = nullptr;
	ArvBuffer *lent_ = nullptr;
	// The pool between connect() and startAcquisition(): ours until Aravis gets it.
	static constexpr int kMaxBuffers = 64;
	ArvBuffer *pool_[kMaxBuffers] = {};
	int pooled_ = 0;
	unsigned long lostHandler_ = 0;
	std::atomic<bool> controlLost_{ false };
	bool started_ = false;
	bool reconnecting_ = false;
	bool acquiring_ = false;
	bool dead_ = false; // found lost: not sent any more commands
	char deviceAddress_[64] = ""; // GigE Vision cameras: for the liveness probe (kept when lost)
	std::thread reaper_; // releases a dead camera (see releaseDeadCamera)
	size_t payload_ = 0;
	bool socketPresized_ = false;
	FrameNumbers numbers_;
	int width_ = 0, height_ = 0;

	using Clock = std::chrono::steady_clock;
	Clock::time_point lastFrame_, lostAt_, lastAttempt_;

	SourceStats stats_;
	AravisStats transport_;
	// Stream counters of connections already closed (Aravis's restart at zero).
	uint64_t closedUnderruns_ = 0, closedMissingFrames_ = 0, closedResent_ = 0, closedMissing_ = 0;
	// The open stream's counters when acquisition started (the Fake stream counts
	// underruns from its creation).
	uint64_t underrunsAtStart_ = 0, missingFramesAtStart_ = 0;
};

} // namespace ports
} // namespace calped
