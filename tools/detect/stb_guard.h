// SPDX-License-Identifier: BSD-2-Clause
// Refuses the inputs stb_image 2.27 (Debian 12's libstb) mishandles, before stb sees them.
// Each check was found by tests/fuzz/fuzz_image and mirrors how stb reads the bytes; stb 2.28
// fixed the same faults upstream. Regression inputs: tests/fuzz/regressions/image/.
//   - JPEG: a Huffman table (DHT) declaring more than 256 codes makes stb write past its
//     code-size and value arrays.
//   - PGM/PPM: a width, height or maximum value with enough digits overflows stb's int;
//     a file shorter than its samples decodes to uninitialised memory instead of failing.
//   - PNG: stb allocates each IDAT chunk's declared length before reading it (a 76-byte
//     file asked for 2 GiB); chunks longer than the rest of the file are refused.
// (stb 2.27 also overruns converting 16-bit PNM to another channel count: image_io asks
// stb for the file's own channels and converts them itself.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace calped::detect_tool {

// False, with a reason, for bytes stb must not be given; true for anything else
// (including files stb will reject by itself).
bool safeForStb(const uint8_t *data, size_t size, std::string &reason);

} // namespace calped::detect_tool
