// SPDX-License-Identifier: BSD-2-Clause
// Dollár's INRIA model from ../shared, converted once per test program by calped-convert,
// for the tests that run a program on real frames.
#pragma once

#include <string>

namespace calped::test {

// The converted model's path, or "" with the reason in skipReason ("no ... (../shared
// models absent)", or "FAIL: ..." when calped-convert exists but failed: a failure, not a
// reason to skip). CALPED_SHARED_DIR overrides ../shared.
const std::string &convertedModel(const std::string &convertPath, std::string &skipReason);

// Removes the scratch folder of the converted model (end of main()).
void removeConvertedModel();

} // namespace calped::test
