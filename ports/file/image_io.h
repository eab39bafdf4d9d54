// SPDX-License-Identifier: BSD-2-Clause
// The one image decoder of the programs and ports (stb_image behind stb_guard's checks and
// a pixel cap) and PNG writing (stb_image_write): the file source decodes with it, and so
// does every program (tools/common links the file port). The core (lib/) has no codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "capped_file.h"

namespace calped {
namespace ports {

// A tightly packed interleaved RGB8 image.
struct RgbImage {
	int width = 0;
	int height = 0;
	std::vector<uint8_t> pixels; // 3 * width * height bytes
};

// Largest image decoded (width x height): 8192 x 8192, 192 MiB as RGB8. A header claiming
// more is refused before any pixel memory is allocated.
constexpr long kMaxImagePixels = 8192L * 8192L;

// The caps on files read whole and the capped reader are in fileio/capped_file.h (shared
// with the C API); the programs name them here.
using files::kMaxCalibrationFileBytes;
using files::kMaxImageFileBytes;
using files::kMaxModelFileBytes;
using files::kMaxTableFileBytes;
using files::readFileBytes;

// Decodes PNG, JPEG, binary PPM or PGM (recognised by their first bytes) to RGB8: grey is
// expanded to three channels, alpha dropped. Other formats stb knows are refused.
// Keeps the file's bytes in a buffer of its own between calls, so decoding frame after
// frame allocates no new file buffer (stb still allocates its own pixels per image).
class ImageDecoder
{
public:
	// Header only (the whole file is read: stb reads a JPEG's tables with its header).
	bool probe(const std::string &path, int &width, int &height, std::string &error);
	// Into `out`, whose pixel buffer is reused when large enough.
	bool decode(const std::string &path, RgbImage &out, std::string &error);
	// Into a caller's buffer of `capacity` bytes; fails if the image does not fit.
	bool decodeInto(const std::string &path, uint8_t *pixels, size_t capacity, int &width,
			int &height, std::string &error);

private:
	std::vector<uint8_t> bytes_;
};

// One-shot forms of ImageDecoder's.
bool probeImage(const std::string &path, int &width, int &height, std::string &error);
bool decodeImage(const std::string &path, RgbImage &out, std::string &error);

// Bytes already in memory (the fuzz target uses this); `name` stands for the file in error
// messages, `maxPixels` caps width x height.
bool decodeImageBytes(const uint8_t *data, size_t size, const std::string &name, RgbImage &out,
		      std::string &error, long maxPixels = kMaxImagePixels);

bool writePng(const std::string &path, const RgbImage &image, std::string &error);

} // namespace ports
} // namespace calped
