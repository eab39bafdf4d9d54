// SPDX-License-Identifier: BSD-2-Clause
// Small hand-made models for the model tests.
#pragma once

#include <cstdint>
#include <vector>

#include <calped/model.h>

namespace calped {
namespace test {

// A valid model: `trees` complete depth-2 trees (7 nodes) with INRIA-like params and
// deterministic, varied node values.
Model makeSmallModel(int32_t trees = 3);

// A valid model whose every parameter differs from ModelParams' defaults, so a field that is
// dropped or swapped on the way through the blob cannot go unnoticed (LDCF filters included).
Model makeUnusualModel();

// The version-1 blob of an ACF model (no filter fields): serializeModel's version-2 blob with
// nFilters and filterSize removed, the version set to 1 and the checksums refreshed.
std::vector<uint8_t> versionOneBlob(const Model &acf);

// Rewrites the header's payload size and both CRCs after a test edited a blob.
void refreshChecksums(std::vector<uint8_t> &blob);

} // namespace test
} // namespace calped
