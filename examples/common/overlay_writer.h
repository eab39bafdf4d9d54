// SPDX-License-Identifier: BSD-2-Clause
// --overlay: saves processed frames as PNG with the detections drawn (tools/common's
// drawRectangle on a canvas allocated once; PNG encoding allocates, so overlays are
// a debugging aid outside the allocation-free path).
#pragma once

#include <string>

#include <calped/detector.h>

#include "frame_source.h"
#include "overlay.h"

namespace calped {
namespace live {

class OverlayWriter
{
public:
	// Creates `dir` if missing. False with `error` when it cannot.
	bool open(const std::string &dir, std::string &error);
	// Writes DIR/<frame id>.png (apps::overlayFileName, as every program names them). RGB8, BGR8 and Gray8 frames are drawn; other
	// formats are skipped (false, with a reason that the caller reports once).
	bool write(const ports::Frame &frame, const Detections &detections, std::string &error);

private:
	std::string dir_;
	apps::RgbImage canvas_;
};

} // namespace live
} // namespace calped
