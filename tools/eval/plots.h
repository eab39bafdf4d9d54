// SPDX-License-Identifier: BSD-2-Clause
// PNG plots through gnuplot, an optional external program: TPR against FPPF per resize
// (one curve per method) and the detector's time per stage. The .dat and .gp files stay
// beside the images so a plot can be redrawn or restyled by hand.
#pragma once

#include <string>
#include <vector>

#include "run.h"

namespace calped::eval_tool {

// Writes the plots into `dir` (which must exist) and appends the images' paths to
// `images`. Without gnuplot it writes the data, sets `notice` and succeeds.
bool writePlots(const std::string &dir, const std::vector<RunResult> &runs,
		std::vector<std::string> &images, std::string &notice, std::string &error);

} // namespace calped::eval_tool
