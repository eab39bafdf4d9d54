// SPDX-License-Identifier: BSD-2-Clause
// Inputs the tests make themselves, so they run without ../shared.
#pragma once

#include <calped/calibration.h>
#include <calped/model.h>

#include <cstdint>
#include <vector>

namespace calped {
namespace test {

// A valid model with the INRIA model's options and nTrees random complete depth-2 trees.
Model randomModel(uint32_t seed, int nTrees = 256);
// The same with LdcfInriaDetector's options: shrink 2, padding 14 x 12 pixels, four random
// 5x5 filters per channel (weights in [-0.5, 0.5]), trees over the 40 filtered channels
// with thresholds around the filtered values' zero.
Model randomLdcfModel(uint32_t seed, int nTrees = 256);

// A level camera 2 m above the ground (metres), looking along +y, focal length 300 px,
// principal point (160, 60): the horizon on row 60 of 320 x 240 frames, people standing
// a few metres away some 100 px tall. false if it could not be made.
bool syntheticCamera(CameraModel &out);

// An RGB image with smooth gradients, edges and noise (deterministic for a seed).
std::vector<uint8_t> randomImage(uint32_t seed, int width, int height);

} // namespace test
} // namespace calped
