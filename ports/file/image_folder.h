// SPDX-License-Identifier: BSD-2-Clause
// The still-image half of the file source: an ordered list of image files, probed for
// their sizes up front and decoded one at a time into a caller-owned RGB8 buffer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <calped/status.h>

#include "image_io.h"

namespace calped {
namespace ports {

// True for .png .jpg .jpeg .ppm .pgm (case-insensitive).
bool isImageFileName(const std::string &path);

// A file becomes a one-frame list; a folder its image files in name order (not recursive).
// IoError for a missing path or a folder without images.
Status listImageFiles(const std::string &path, std::vector<std::string> &files);

// Reads every file's header: undecodable files fail before streaming starts, and the
// largest size sizes the buffer. IoError naming the file. `decoder` keeps a file buffer as
// large as the largest file, so decoding them later needs no new one.
Status probeImageFiles(ImageDecoder &decoder, const std::vector<std::string> &files,
		       int &maxWidth, int &maxHeight);

// Decodes one file to tightly packed RGB8 into `pixels` (capacity `capacity` bytes) with
// `decoder` (image_io.h: the guarded decoder, whose file buffer is reused frame to frame).
Status decodeImageInto(ImageDecoder &decoder, const std::string &path, uint8_t *pixels,
		       size_t capacity, int &width, int &height);

} // namespace ports
} // namespace calped
