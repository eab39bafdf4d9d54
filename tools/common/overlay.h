// SPDX-License-Identifier: BSD-2-Clause
// Draws detections onto a copy of the frame (plain pixel writes, no drawing library).
#pragma once

#include <calped/detector.h>

#include "image_io.h"

namespace calped::apps {

using ports::RgbImage;

// Draws an axis-aligned rectangle outline `thickness` pixels wide, inside the box,
// clipped to the image. Boxes entirely outside leave the image unchanged.
void drawRectangle(RgbImage &image, float x, float y, float w, float h, int thickness,
		   const uint8_t rgb[3]);

// The frame with every detection as a 2-pixel green rectangle.
RgbImage renderOverlay(const RgbImage &frame, const Detections &detections);

} // namespace calped::apps
