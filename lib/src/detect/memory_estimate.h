// SPDX-License-Identifier: BSD-2-Clause
// What a detector's buffers will take, known before any is allocated, so that create()
// can refuse a configuration beyond DetectorConfig::memoryBudgetBytes instead of taking
// gigabytes (a model with a large nOctUp, a huge frame at a large resize).
#pragma once

#include <cstdint>

#include <calped/detector.h>
#include <calped/model.h>

namespace calped {

// Bytes of the buffers that grow with the frame: the largest pyramid image (the frame at
// resize * 2^nOctUp) with its channels and resampling buffers, the frame-sized colour
// planes, and for LDCF each thread's filter stage. An estimate from their sizes that errs
// high (docs/errors.md); the trees and candidate lists (small, fixed) are left out.
uint64_t estimateDetectorBytes(const ModelParams &params, const DetectorConfig &config);

} // namespace calped
