// SPDX-License-Identifier: BSD-2-Clause
// Reading a whole file with a cap by kind of file, and only a regular file: what the
// programs, the file source and the C API read (docs/errors.md, "Limits checked before
// any work"). No dependency beyond the C++ standard library and POSIX.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace calped {
namespace files {

// Caps on the files read whole, by kind: a larger file is refused before it is read.
constexpr size_t kMaxImageFileBytes = size_t(256) << 20;       // an 8192x8192 PPM and then some
constexpr size_t kMaxModelFileBytes = size_t(64) << 20;        // the INRIA blob is 0.2 MiB
constexpr size_t kMaxCalibrationFileBytes = size_t(4) << 20;   // calibrations are a few KiB
constexpr size_t kMaxTableFileBytes = size_t(512) << 20;       // CSV, ground truth, correspondences

// Reads a whole regular file into `out`, reusing its capacity; a FIFO, device, socket or
// folder is refused (a FIFO would block, /dev/zero never ends), and so is a file over
// maxBytes. `what` names the file's role in the error ("model "). Allocates nothing when
// `out` already has the capacity (the file source reads frame after frame with it).
bool readFileBytes(const std::string &path, std::vector<uint8_t> &out, std::string &error,
		   const std::string &what, size_t maxBytes);

} // namespace files
} // namespace calped
