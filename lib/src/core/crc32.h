// SPDX-License-Identifier: BSD-2-Clause
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {

// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, init and final xor 0xFFFFFFFF),
// the checksum of zlib and PNG: crc32("123456789") == 0xCBF43926.
uint32_t crc32(const uint8_t *data, size_t size);

} // namespace calped
