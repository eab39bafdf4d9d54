// SPDX-License-Identifier: BSD-2-Clause
// Conversions from the toolbox's float values to calped's fixed-point model fields.
// thresholdToFixed is public (calped/model.h); the leaf conversion is internal because only
// the converter and the tests need it.
#pragma once

#include <cstdint>

#include <calped/model.h>

namespace calped {

// Leaf value in score fixed point: round(value * 2^kScoreFracBits), halves away from zero,
// clamped to int32. NaN gives 0 (the converter refuses non-finite leaves before calling this).
int32_t leafValueToFixed(double value);

// LDCF filter weight in Q15 (kFilterFracBits): round(value * 2^15), halves away from zero,
// clamped to int32 (validateModel then bounds it to [-2^15, 2^15]). NaN gives 0.
int32_t filterWeightToFixed(double value);

} // namespace calped
