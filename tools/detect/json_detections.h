// SPDX-License-Identifier: BSD-2-Clause
// The detections of one frame as a JSON array, shared by calped-detect's JSON Lines and the
// live examples' output (docs/cli.md, docs/ports.md).
#pragma once

#include <cstdio>

#include <calped/detector.h>

namespace calped::detect_tool {

// [{"x":..,"y":..,"w":..,"h":..,"score":..[,"ground_x":..,"ground_y":..][,"world_height":..]},...]
// fprintf only: nothing is allocated.
void writeJsonDetections(FILE *f, const Detections &detections);

} // namespace calped::detect_tool
