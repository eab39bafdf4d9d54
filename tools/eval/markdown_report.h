// SPDX-License-Identifier: BSD-2-Clause
// The Markdown page of an evaluation (the main job's docs/results.md body): tables, then
// the plots and overlays linked relative to the page.
#pragma once

#include <string>
#include <vector>

#include "run.h"

namespace calped::eval_tool {

struct MarkdownContext {
	std::string groundTruth;       // path as given
	std::string frames;            // Markdown: "`data/pets/frames` (795 frames)"
	std::vector<std::string> plots;    // image paths as written
	std::vector<std::string> overlays; // image paths as written
	double overlayScore = 0;
};

// `pagePath` is where the page will be written; image links are made relative to it.
std::string markdownReport(const std::string &pagePath, const std::vector<RunResult> &runs,
			   const MarkdownContext &context);

} // namespace calped::eval_tool
