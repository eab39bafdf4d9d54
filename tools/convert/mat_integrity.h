// SPDX-License-Identifier: BSD-2-Clause
// The checks libmatio does not make on a MAT v5 file: its top-level elements must tile the
// file exactly (a truncated file, or a length changed, is refused), and every compressed
// element must inflate completely with its zlib checksum verified (matio stops reading a
// compressed variable once it has what it wants, so a changed byte inside one converted
// "successfully" into a different model). A pure function, fuzzed (tests/fuzz/fuzz_mat.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace calped {
namespace convert {

// Most bytes one compressed element may inflate to (the toolbox's models: a few MB).
constexpr size_t kMaxInflatedBytes = size_t(1) << 30;

// True when `data` is a well-formed MAT v5 file at the level of its top-level elements;
// else false and a message (without the file name) saying what and where.
bool checkMatIntegrity(const uint8_t *data, size_t size, std::string &error);

} // namespace convert
} // namespace calped
