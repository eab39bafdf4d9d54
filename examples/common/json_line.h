// SPDX-License-Identifier: BSD-2-Clause
// The live examples' per-frame output: one JSON object per line (format in docs/ports.md).
#pragma once

#include <cstdio>

#include <calped/detector.h>

#include "frame_source.h"

namespace calped {
namespace live {

// {"frame":ID,"timestamp_ns":T,"width":W,"height":H,"ms":M,"detections":[{"x":..,"y":..,
// "w":..,"h":..,"score":..[,"ground_x":..,"ground_y":..][,"world_height":..]}]}
// fprintf only: nothing is allocated per frame.
void writeJsonLine(FILE *f, const ports::Frame &frame, double ms, const Detections &detections);

} // namespace live
} // namespace calped
