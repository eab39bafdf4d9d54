// SPDX-License-Identifier: BSD-2-Clause
// detector.opts (Dollár's toolbox) -> calped::ModelParams, refusing what calped cannot run.
#pragma once

#include <calped/model.h>
#include <calped/status.h>

#include "mat_reader.h"

namespace calped {
namespace convert {

// Reads every option calped uses but LDCF's filters (readDetectorFilters). Fails with
// ModelUnsupported for a colour space other than LUV, disabled or custom channels, HOG channels and NMS types other than
// 'maxg'; with ModelInvalid for missing or malformed fields. Ranges are left to validateModel.
Status readDetectorOpts(const MatNode &opts, ModelParams &out);

} // namespace convert
} // namespace calped
