// SPDX-License-Identifier: BSD-2-Clause
#include "markdown_report.h"

#include <cstdio>
#include <filesystem>

#include "report.h"

namespace calped::eval_tool {

namespace {

std::string relativeTo(const std::string &pagePath, const std::string &image)
{
	namespace fs = std::filesystem;
	std::error_code ec;
	const fs::path page = fs::absolute(pagePath, ec).parent_path();
	const fs::path target = fs::absolute(image, ec);
	const fs::path rel = target.lexically_normal().lexically_relative(page.lexically_normal());
	return rel.empty() ? image : rel.generic_string();
}

std::string baseName(const std::string &path)
{
	return std::filesystem::path(path).filename().string();
}

} // namespace

std::string markdownReport(const std::string &pagePath, const std::vector<RunResult> &runs,
			   const MarkdownContext &c)
{
	std::string md;
	md += "Frames: " + c.frames + "; ground truth: `" + c.groundTruth + "`. Protocol, columns and "
	      "counters: [evaluation.md](evaluation.md).\n\n";
	md += "### Accuracy and cost\n\n" + accuracyTable(runs) + "\n";
	md += "TPR and FPPF count every detection the detector reports (greedy matching by score, "
	      "IoU >= 0.5); TPR (any) is the thesis's criterion (some detection at IoU > 0.5); "
	      "LAMR is the log-average miss rate over FPPF 10^-2..10^0. ms/frame is the detector's own "
	      "time (FrameStats::msTotal, mean), without decoding.\n\n";
	const std::string stages = stageTable(runs);
	if (!stages.empty())
		md += "### Detector time per stage (ms/frame, means)\n\n" + stages + "\n";
	if (!c.plots.empty()) {
		md += "### Plots\n\n";
		for (const std::string &p : c.plots)
			md += "![" + baseName(p) + "](" + relativeTo(pagePath, p) + ")\n\n";
	}
	if (!c.overlays.empty()) {
		char score[64];
		std::snprintf(score, sizeof(score), "%g", c.overlayScore);
		// Listed, not shown: they are large and not kept in the repository, so a page
		// committed with them would link images that a checkout does not have.
		md += "### Sample frames\n\nGround truth in blue, detections scoring at least " +
		      std::string(score) +
		      " in green. The run writes them beside this page (not in the repository: "
		      "about 750 KB each):\n\n";
		for (const std::string &p : c.overlays)
			md += "- `" + relativeTo(pagePath, p) + "`\n";
		md += "\n";
	}
	return md;
}

} // namespace calped::eval_tool
