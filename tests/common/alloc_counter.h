// SPDX-License-Identifier: BSD-2-Clause
// Counts calls of the global operator new (replaced in alloc_counter.cpp, so a binary that
// links it has its own allocation functions) while enabled, to prove that detect() and the
// ports' per-frame paths allocate nothing. C allocations inside third-party libraries
// (stb_image, GLib) are malloc calls and not counted; docs/ports.md says so.
#pragma once

namespace calped {
namespace test {

void startCountingAllocations();
// Stops counting and returns the allocations seen since start.
long stopCountingAllocations();

} // namespace test
} // namespace calped
