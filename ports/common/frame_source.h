// SPDX-License-Identifier: BSD-2-Clause
// The interface every capture port implements (file sequences, Aravis, libcamera), so
// everything above a port (examples, tests, the soak) is written once and runs without
// hardware on the file source.
//
// Lifetime: next() lends one frame. Its pixels stay valid and unchanged until the next
// call to next(), release(), stop() or the source's destruction, whichever comes first;
// run the detector on it in between. A source never allocates per frame after start():
// buffers come from a pool fixed at open time.
#pragma once

#include <cstdint>

#include <calped/image.h>
#include <calped/status.h>

namespace calped {
namespace ports {

struct Frame {
	ImageView image;          // borrowed, see the lifetime rule above
	uint64_t id = 0;          // the source's frame number (camera block id, file index)
	int64_t timestampNs = 0;  // capture time from the source, or arrival time if none
};

// Counters since start(). Every frame the camera produced and we did not hand out is
// in exactly one of dropped / incomplete.
struct SourceStats {
	uint64_t delivered = 0;   // frames handed out by next()
	uint64_t dropped = 0;     // complete frames discarded by the drop policy (consumer too slow)
	uint64_t incomplete = 0;  // frames the transport delivered damaged (missing packets, ...)
	uint64_t timeouts = 0;    // next() calls that waited timeoutMs without a frame
	uint64_t restarts = 0;    // times the source reconnected after losing its camera
};

class FrameSource
{
public:
	virtual ~FrameSource() = default;

	// Starts streaming. Errors: IoError / CameraNotFound / CameraError with a message.
	virtual Status start() = 0;

	// Waits up to timeoutMs for the next complete frame and lends it (see above).
	// Returns EndOfStream when a finite source is exhausted, Timeout when no frame came
	// (counted), CameraLost when the device stopped answering or disappeared.
	virtual Status next(Frame &frame, int timeoutMs) = 0;

	// Gives the lent frame back early (next() does it implicitly).
	virtual void release() = 0;

	// Stops streaming and returns every buffer; safe to call twice, and after errors.
	virtual void stop() = 0;

	virtual SourceStats stats() const = 0;

	// Human-readable identity, e.g. "file:data/pets/frames (795 frames)".
	virtual const char *name() const = 0;

	// The largest frame the source will lend, when it knows before streaming (a file
	// sequence, a camera whose region is set); false when only the first frame will tell.
	// Lets the consumer size its buffers (Detector::create) before the first frame.
	virtual bool frameSize(int &width, int &height) const
	{
		(void)width;
		(void)height;
		return false;
	}
};

} // namespace ports
} // namespace calped
