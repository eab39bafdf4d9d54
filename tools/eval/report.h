// SPDX-License-Identifier: BSD-2-Clause
// The outputs people and scripts read: the thesis-style Markdown tables and the JSON file.
#pragma once

#include "file_io.h"

#include <string>
#include <vector>

#include "run.h"

namespace calped::eval_tool {

using apps::writeTextFile;

// | Method | Resize | Scales (Octaves) | CApF | TPR | FPPF | TPR (any) | LAMR | ms/frame | peak RSS |
std::string accuracyTable(const std::vector<RunResult> &runs);
// Per-stage detector time (runs with counters only; empty string if none).
std::string stageTable(const std::vector<RunResult> &runs);

// One JSON object per run, in an array.
std::string runsJson(const std::vector<RunResult> &runs);


} // namespace calped::eval_tool
