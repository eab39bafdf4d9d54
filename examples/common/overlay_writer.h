// SPDX-License-Identifier: BSD-2-Clause
// --overlay: saves processed frames as PNG with the detections drawn (tools/detect's
// drawRectangle on a canvas allocated once; PNG encoding allocates, so overlays are
// a debugging aid outside the allocation-free path).
#pragma once

#include <string>

#include <calped/detector.h>

#include "frame_source.h"
#include "image_io.h"

namespace calped {
namespace live {

class OverlayWriter
{
public:
	// Creates `dir` if missing. False with `error` when it cannot.
	bool open(const std::string &dir, std::string &error);
	// Writes DIR/<frame id, 8 digits>.png. RGB8, BGR8 and Gray8 frames are drawn; other
	// formats are skipped (false, with a reason that the caller reports once).
	bool write(const ports::Frame &frame, const Detections &detections, std::string &error);

private:
	std::string dir_;
	detect_tool::RgbImage canvas_;
};

} // namespace live
} // namespace calped
