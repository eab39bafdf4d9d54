// SPDX-License-Identifier: BSD-2-Clause
// Counts calls of the global operator new (replaced in alloc_counter.cpp) while enabled,
// to prove a streaming loop allocates nothing per frame. C allocations inside third-party
// libraries (stb_image, GLib) are malloc calls and not counted; docs/ports.md says so.
#pragma once

namespace calped {
namespace test {

void startCountingAllocations();
// Stops counting and returns the allocations seen since start.
long stopCountingAllocations();

} // namespace test
} // namespace calped
