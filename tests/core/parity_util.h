// SPDX-License-Identifier: BSD-2-Clause
// Shared by the parity tests of every model: detections of PETS frames against a toolbox
// CSV, and pyramid levels against the toolbox's float32 dump of a level.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <calped/detector.h>
#include <calped/model.h>

#include "pyramid/pyramid.h"

namespace calped {
namespace test {

struct Box {
	double x, y, w, h, score;
};

// frame,x,y,w,h,score lines (a header and '#' lines are skipped), by frame.
std::map<int, std::vector<Box>> readDetections(const std::string &path);

// Runs `model` (a blob path) over PETS frames 1..frames (CALPED_PARITY_FRAMES may lower
// it) and checks the detections against the toolbox's: at least minMatched of each side's
// boxes with score >= 10 have a box of the other at IoU >= 0.8, and the median relative
// score difference of the matches is at most 3%. Prints the figures. Skips without data.
// `cpu`: whose rcpps the reference's toolbox ran with (docs/parity.md).
void expectDetectionParity(const std::string &modelBlob, const std::string &refPath, int frames,
			   double resize, ResizeAt where, double minMatched,
			   ToolboxCpu cpu = ToolboxCpu::Intel);

// Level `level` (0-based) of a prepared pyramid level against the toolbox's float32 dump in
// Matlab column-major [h w c] order at `offset` floats: per channel, mean |diff| <= 1% of
// the channel's mean (orientMean for channels 4-9 when given) and 99th percentile <= 5% of
// its max. Returns the floats it read.
size_t expectLevelWithinTolerance(const LevelChannels &lc, int channels, const std::vector<float> &ref,
				  size_t offset, const char *what, double orientMean = 0.01);

// PETS frame 1 through the pyramid of the toolbox's model `name` (its blob made by
// calped-convert), as the AMD EPYC that made the references computed it (its rcpps:
// docs/parity.md), beside that model's dump of levels 1-2 (pyr_frame1_levels1-2.bin).
struct ToolboxFrame1 {
	Model model;
	Pyramid pyramid;
	std::vector<float> reference;
};
enum class Frame1 { Ready, Absent, Failed };
// Absent: ../shared, the blob or the PETS frames are missing (the caller skips); Failed:
// reported with ADD_FAILURE.
Frame1 toolboxPyramidFrame1(const char *name, ToolboxFrame1 &out);

} // namespace test
} // namespace calped
