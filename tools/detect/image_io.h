// SPDX-License-Identifier: BSD-2-Clause
// Image decoding and PNG writing (stb_image / stb_image_write).
#pragma once

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

// Decodes PNG, JPEG, PPM or PGM to RGB8; grey images are expanded to three channels.
bool decodeImage(const std::string &path, RgbImage &out, std::string &error);

bool writePng(const std::string &path, const RgbImage &image, std::string &error);

} // namespace calped::detect_tool
