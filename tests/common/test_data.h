// SPDX-License-Identifier: BSD-2-Clause
// Where the tests find their inputs: ../shared (reference vectors, models) and the
// decoded PETS frames (data/pets/frames, made by scripts/fetch-pets.sh).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace calped {
namespace test {

// ../shared as seen from the project root, or "" when absent.
std::string sharedDir();
// Decoded PETS frame k (1-based) or "" when the frames have not been fetched.
std::string petsFrame(int k);
// A converted INRIA model blob made for the tests (converting it if needed), or "".
std::string inriaModelBlob();
// The same for another of the toolbox's detectors in ../shared/models/dollar-toolbox, by
// its .mat name without the extension (e.g. "AcfCaltech+Detector").
std::string toolboxModelBlob(const std::string &name);

struct RgbImage {
	int width = 0, height = 0;
	std::vector<uint8_t> pixels; // interleaved RGB
};
bool loadRgb(const std::string &path, RgbImage &out);
// The image at `path`, or a 768x576 synthetic one (randomImage) when path is empty; false
// with a message on stderr naming `program` when the file cannot be decoded (benchmarks).
bool loadFrameOrSynthetic(const std::string &path, const char *program, RgbImage &out);

bool readFile(const std::string &path, std::vector<uint8_t> &out);
std::vector<float> readFloats(const std::string &path);

// Summary of |a - b| over n values.
struct DiffStats {
	double meanAbs = 0, p99Abs = 0, maxAbs = 0;
	double meanA = 0, maxA = 0;
};
DiffStats compare(const float *ours, const float *ref, size_t n);

} // namespace test
} // namespace calped
