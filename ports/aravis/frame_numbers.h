// SPDX-License-Identifier: BSD-2-Clause
// The frame number the Aravis port lends as Frame::id: the camera's block id made to grow
// without end. GigE Vision 1.x block ids are 16 bits, skip 0 and wrap from 65535 to 1
// (Aravis's simulators start at 65401, so a stream wraps after 135 frames); GigE Vision 2
// and USB3 Vision ids are 64 bits. No camera or Aravis code here, so it is tested alone.
#pragma once

#include <cstdint>

namespace calped {
namespace ports {

class FrameNumbers
{
public:
	// The number of the frame with this block id. Aravis hands buffers out in block-id
	// order (it completes frames in order and discards late packets of older ones), so
	// every id is taken as newer than the one before: forward by its distance on the
	// 16-bit circle (65535 -> 1 is one step), or, when the id went back, by one (the
	// camera restarted its counter; the gap is unknown and not counted). timestampNs (the
	// frame's arrival, monotonic; <= 0: none) measures the frame interval, from which the
	// frames lost while a restarted connection was away are estimated.
	uint64_t next(uint64_t blockId, int64_t timestampNs = 0);
	// A new connection: its ids start afresh; numbers go on from the last one plus the
	// frames estimated lost meanwhile (the time away over the interval seen before, less one).
	void restart() { restarted_ = true; }
	// Frames skipped by the block ids so far (all connections), estimated ones included.
	uint64_t unseen() const { return unseen_; }
	// Of those, the frames estimated lost across restarts.
	uint64_t lostAcrossRestarts() const { return lostAcrossRestarts_; }

private:
	bool started_ = false;   // a first id was seen
	bool restarted_ = false; // the next id starts a new connection
	uint64_t lastId_ = 0;    // the camera's last block id
	uint64_t number_ = 0;    // the last number given
	uint64_t unseen_ = 0;
	int64_t lastTimestampNs_ = 0;     // the last frame's arrival (0: none)
	double intervalNs_ = 0;           // smoothed time per id step (0: not measured yet)
	uint64_t lostAcrossRestarts_ = 0;
};

} // namespace ports
} // namespace calped
