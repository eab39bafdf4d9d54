// SPDX-License-Identifier: BSD-2-Clause
// What ffprobe prints for `-show_entries stream=width,height -of csv=p=0:s=x`: "WxH" and a
// line end. A pure function, so that it can be tested and fuzzed without ffprobe.
#pragma once

#include <cstddef>

namespace calped {
namespace ports {

// Largest side accepted from ffprobe; the detector's own maximum is 16384.
constexpr int kMaxProbedSide = 16384;

// True and the size when `text` (size bytes, not NUL-terminated) is exactly two decimal
// numbers 1..kMaxProbedSide without leading zeros joined by 'x', then only white space (ffprobe's line end; a
// second stream's line is refused, as is a sign, a leading space or trailing junk).
bool parseProbedSize(const char *text, size_t size, int &width, int &height);

} // namespace ports
} // namespace calped
