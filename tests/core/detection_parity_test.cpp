// SPDX-License-Identifier: BSD-2-Clause
// Detections on PETS frames 1-50 against Dollár's toolbox (acfDetect with the INRIA
// model), at native size and with the frame upscaled 2x.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <calped/detector.h>

#include "parity_util.h"
#include "test_data.h"

using namespace calped;

namespace {

void runParity(const char *refFile, double resize, double minMatched, bool resizeInPyramid = false)
{
	const std::string shared = test::sharedDir();
	const std::string blobPath = test::inriaModelBlob();
	if (shared.empty() || blobPath.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	test::expectDetectionParity(blobPath, shared + "/reference/dollar-toolbox-pets/" + refFile, 50,
				    resize, resizeInPyramid ? ResizeAt::Pyramid : ResizeAt::Frame,
				    minMatched);
}

} // namespace

// Target (issue #2): 95% both ways (the misses left are NMS ties between neighbouring
// windows whose scores differ by less than the remaining score noise, docs/parity.md).
TEST(DetectionParity, Frames1To50Native) { runParity("dets_native.csv", 1.0, 0.95); }
TEST(DetectionParity, Frames1To50Resize2) { runParity("dets_up2x.csv", 2.0, 0.95); }
// Resize 2 inside the pyramid is the toolbox's nOctUp = 1 on the native frame.
TEST(DetectionParity, Frames1To50Resize2InPyramid)
{
	runParity("dets_octup1.csv", 2.0, 0.95, true);
}
