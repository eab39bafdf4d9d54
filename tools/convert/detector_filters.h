// SPDX-License-Identifier: BSD-2-Clause
// detector.opts.filters (LDCF's decorrelation filters) -> calped::Model filters in Q15.
#pragma once

#include <calped/model.h>
#include <calped/status.h>

#include "mat_reader.h"

namespace calped {
namespace convert {

// An absent or empty opts.filters leaves the model ACF (no filters). Otherwise the array must
// be size x size x 10 x nFilters (Matlab drops a trailing 1: size x size x 10 is one filter),
// size odd, every weight finite and in [-1, 1]; weights are stored in Q15 in calped's order
// (filter, channel, row, column). Failures are ModelInvalid naming the field.
Status readDetectorFilters(const MatNode &opts, Model &model);

} // namespace convert
} // namespace calped
