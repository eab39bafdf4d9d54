// SPDX-License-Identifier: BSD-2-Clause
// Image decoding and PNG writing (stb_image / stb_image_write).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace calped::detect_tool {

// A tightly packed interleaved RGB8 image owned by the tool.
struct RgbImage {
	int width = 0;
	int height = 0;
	std::vector<uint8_t> pixels; // 3 * width * height bytes
};

// Reads only the header: cheap enough to size the detector for every frame up front.
bool probeImage(const std::string &path, int &width, int &height, std::string &error);

// Largest image the tools decode (width x height): 8192 x 8192, 192 MiB as RGB8. A header
// claiming more is refused before any pixel memory is allocated.
constexpr long kMaxImagePixels = 8192L * 8192L;

// Decodes PNG, JPEG, PPM or PGM to RGB8; grey images are expanded to three channels.
// Other formats stb knows (GIF, BMP, PSD, ...) are refused: the tools document only these.
bool decodeImage(const std::string &path, RgbImage &out, std::string &error);

// The same on bytes already in memory (the fuzz target uses this); `name` stands for the
// file in error messages, `maxPixels` caps width x height.
bool decodeImageBytes(const uint8_t *data, size_t size, const std::string &name, RgbImage &out,
		      std::string &error, long maxPixels = kMaxImagePixels);

bool writePng(const std::string &path, const RgbImage &image, std::string &error);

} // namespace calped::detect_tool
