// SPDX-License-Identifier: BSD-2-Clause
// Input text quoted in an error message: the one escaping of the core, the C API and the
// programs (calibration loaders, the detections-CSV and ground-truth readers,
// calped-calibrate's CSV, file names). A message stays one printable line of valid UTF-8
// and of bounded length whatever the input holds (docs/errors.md).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace calped {

// Most input bytes a message quotes; more is cut (at a character boundary) and "..." added.
constexpr size_t kExcerptBytes = 60;
// File names are quoted at more length: a path is the user's own, and cut it names nothing.
constexpr size_t kExcerptPathBytes = 160;

// Writes into `out` (outSize bytes, NUL-terminated, outSize >= 1) at most maxBytes bytes of
// `text`, each control byte (below 0x20, 0x7f) and each byte that is not part of a
// well-formed UTF-8 character as '?', then "..." when text was longer. Allocates nothing
// (the per-frame path may report errors). Returns out.
const char *excerpt(std::string_view text, char *out, size_t outSize, size_t maxBytes = kExcerptBytes);

// The same as a string (for the programs' messages).
std::string excerpt(std::string_view text, size_t maxBytes = kExcerptBytes);

// Length of the well-formed UTF-8 character at s[0..left), or 0 when it is not one
// (overlong forms, surrogates and code points above U+10FFFF are not).
size_t utf8CharLength(const unsigned char *s, size_t left);

} // namespace calped
