// SPDX-License-Identifier: BSD-2-Clause
// Refuses the inputs stb_image 2.27 (Debian 12's libstb) mishandles, before stb sees them.
// Each check was found by tests/fuzz/fuzz_image and mirrors how stb reads the bytes; stb 2.28
// fixed the same faults upstream. Regression inputs: tests/fuzz/regressions/image/.
//   - JPEG: a Huffman table (DHT) declaring more than 256 codes makes stb write past its
//     code-size and value arrays.
//   - PGM/PPM: a width, height or maximum value with enough digits overflows stb's int;
//     a file shorter than its samples decodes to uninitialised memory instead of failing;
//     16-bit samples come out in the host's byte order (the low byte on x86 and ARM), and
//     converting their channels overran stb's buffer: only 8-bit PGM/PPM is accepted.
//   - PNG: stb allocates each IDAT chunk's declared length before reading it (a 76-byte
//     file asked for 2 GiB): chunks longer than the rest of the file are refused; a first
//     IDAT that is empty makes stb copy into a null pointer: refused.
// (image_io also asks stb for the file's own channels and expands them itself, so stb's
// channel conversion, where the 16-bit overrun was, is never used.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace calped::ports {

// False, with a reason, for bytes stb must not be given; true for anything else
// (including files stb will reject by itself).
bool safeForStb(const uint8_t *data, size_t size, std::string &reason);

} // namespace calped::ports
