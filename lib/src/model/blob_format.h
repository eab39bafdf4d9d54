// SPDX-License-Identifier: BSD-2-Clause
// Constants of the model blob, version 2 (version 1 still loads). docs/model-format.md is the specification;
// the offsets here must stay in step with its table.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {
namespace blob {

constexpr uint8_t kMagic[8] = { 'C', 'A', 'L', 'P', 'E', 'D', 'M', 0 };
constexpr uint32_t kVersion = 2;        // what serializeModel writes
constexpr uint32_t kOldestVersion = 1;  // the oldest loadModel reads

// Header: magic, version, header size, payload size, payload CRC, header CRC.
constexpr size_t kHeaderSize = 32;
constexpr size_t kVersionOffset = 8;
constexpr size_t kHeaderSizeOffset = 12;
constexpr size_t kPayloadSizeOffset = 16;
constexpr size_t kPayloadCrcOffset = 24;
constexpr size_t kHeaderCrcOffset = 28; // CRC-32 of header bytes [0, 28)

// Payload: 28 parameter words (version 2: 30, with nFilters and filterSize), nTrees,
// nodesPerTree, treeDepth, name length (all 4 bytes), then the name bytes, (version 2)
// the filter weights, and the four node arrays of 4-byte words.
constexpr size_t kParamWordsV1 = 28;
constexpr size_t kParamWords = 30;
constexpr size_t kFixedPayloadSizeV1 = 4 * (kParamWordsV1 + 3 + 1);
constexpr size_t kFixedPayloadSize = 4 * (kParamWords + 3 + 1);
constexpr size_t kBytesPerNode = 4 * 4; // fids, thrs, child, hs

// Limits checked by validateModel (and therefore by loadModel).
constexpr uint32_t kMaxNameLength = 256;
constexpr int32_t kMaxTrees = 1 << 16;
constexpr int32_t kMaxNodesPerTree = 255;
constexpr int32_t kMaxTreeDepth = 8;
constexpr int32_t kMaxFilters = 16;     // LDCF uses 4 per channel
constexpr int32_t kMaxFilterSize = 15;  // odd; LDCF uses 5
constexpr int32_t kMaxFilterWeight = 1 << 15; // |weight| <= 1.0 in Q15

} // namespace blob
} // namespace calped
