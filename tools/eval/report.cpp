// SPDX-License-Identifier: BSD-2-Clause
#include "report.h"

#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "json_frame.h"
#include "overlay_frames.h"

namespace calped::eval_tool {

namespace {

std::string format(const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 1, 2)))
#endif
	;

std::string format(const char *fmt, ...)
{
	char buf[256];
	va_list ap;
	va_start(ap, fmt);
	std::vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	return buf;
}

// NaN (no ground truth) prints as "n/a" rather than a misleading number.
std::string fixed(double v, int decimals)
{
	return std::isfinite(v) ? format("%.*f", decimals, v) : "n/a";
}

std::string resizeCell(const RunResult &r)
{
	return r.resize > 0 ? resizeLabel(r.resize) : "-";
}

// "29 (4)" when every frame had the same pyramid, else the means.
std::string scalesCell(const RunCounters &c)
{
	if (c.frames == 0)
		return "-";
	if (c.levelsMin == c.levelsMax && c.octavesMin == c.octavesMax)
		return format("%d (%d)", c.levelsMin, c.octavesMin);
	return format("%.1f (%.1f)", c.levelsMean, c.octavesMean);
}

std::string jsonNumber(double v)
{
	return std::isfinite(v) ? format("%.9g", v) : "null";
}

} // namespace

std::string accuracyTable(const std::vector<RunResult> &runs)
{
	std::string t = "| Method | Resize | Scales (Octaves) | CApF | TPR | FPPF | TPR (any) | LAMR "
			"| ms/frame | peak RSS (MiB) |\n"
			"|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
	for (const RunResult &r : runs) {
		const Evaluation &e = r.evaluation;
		const RunCounters &c = r.counters;
		t += "| " + r.method + " | " + resizeCell(r) + " | ";
		if (r.hasCounters)
			t += scalesCell(c) + " | " + format("%.0f", c.windowsMean) + " | ";
		else
			t += "- | - | ";
		t += fixed(e.tpr, 3) + " | " + fixed(e.fppf, 2) + " | " + fixed(e.tprAny, 3) + " | " +
		     fixed(e.logAverageMissRate, 3) + " | ";
		if (r.hasCounters)
			t += format("%.1f | %.1f |", c.msTotal, c.peakRssKib / 1024.0);
		else
			t += "- | - |";
		t += "\n";
	}
	return t;
}

std::string stageTable(const std::vector<RunResult> &runs)
{
	std::string t = "| Method | Resize | resize | channels (octaves) | approximated levels "
			"| classification | candidates | suppression | other | total | median total "
			"| frame decode |\n"
			"|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
	bool any = false;
	for (const RunResult &r : runs) {
		if (!r.hasCounters)
			continue;
		any = true;
		const RunCounters &c = r.counters;
		t += "| " + r.method + " | " + resizeCell(r) + " | " +
		     format("%.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
			    c.msResize, c.msChannels, c.msApprox, c.msClassify, c.msCandidates, c.msNms,
			    c.msOther(),
			    c.msTotal, c.msTotalMedian, c.msDecode);
	}
	return any ? t : std::string();
}

std::string runsJson(const std::vector<RunResult> &runs)
{
	const std::vector<double> refs = missRateReferences();
	std::string j = "[";
	for (size_t i = 0; i < runs.size(); i++) {
		const RunResult &r = runs[i];
		const Evaluation &e = r.evaluation;
		const RunCounters &c = r.counters;
		j += i ? ",\n  {" : "\n  {";
		j += "\"method\": " + apps::jsonString(r.method);
		j += ", \"resize\": " + (r.resize > 0 ? jsonNumber(r.resize) : "null");
		j += ", \"frames\": " + std::to_string(r.frames);
		j += ", \"gt_boxes\": " + std::to_string(e.groundTruth);
		j += ", \"ignore_boxes\": " + std::to_string(e.ignoreBoxes);
		j += ", \"detections\": " + std::to_string(e.detections);
		j += ", \"true_positives\": " + std::to_string(e.truePositives);
		j += ", \"false_positives\": " + std::to_string(e.falsePositives);
		j += ", \"ignored_detections\": " + std::to_string(e.ignoredDetections);
		j += ",\n   \"tpr\": " + jsonNumber(e.tpr);
		j += ", \"tpr_any\": " + jsonNumber(e.tprAny);
		j += ", \"fppf\": " + jsonNumber(e.fppf);
		j += ", \"log_avg_miss_rate\": " + jsonNumber(e.logAverageMissRate);
		j += ", \"miss_rate_at_fppf\": [";
		for (size_t k = 0; k < refs.size(); k++)
			j += (k ? ", [" : "[") + jsonNumber(refs[k]) + ", " +
			     jsonNumber(k < e.missAtReference.size() ? e.missAtReference[k] : NAN) + "]";
		j += "]";
		if (r.hasCounters) {
			const bool fixedPyramid = c.levelsMin == c.levelsMax && c.octavesMin == c.octavesMax;
			j += ",\n   \"scales\": " + jsonNumber(fixedPyramid ? c.levelsMin : c.levelsMean);
			j += ", \"octaves\": " + jsonNumber(fixedPyramid ? c.octavesMin : c.octavesMean);
			j += ", \"capf\": " + jsonNumber(c.windowsMean);
			j += ", \"candidates_per_frame\": " + jsonNumber(c.candidatesMean);
			j += ", \"dropped_windows\": " + std::to_string(c.droppedWindows);
			j += ", \"frames_too_small\": " + std::to_string(c.tooSmall);
			j += ",\n   \"ms_per_frame\": " + jsonNumber(c.msTotal);
			j += ", \"ms_per_frame_median\": " + jsonNumber(c.msTotalMedian);
			j += ", \"ms_resize\": " + jsonNumber(c.msResize);
			j += ", \"ms_channels\": " + jsonNumber(c.msChannels);
			j += ", \"ms_approx\": " + jsonNumber(c.msApprox);
			j += ", \"ms_classify\": " + jsonNumber(c.msClassify);
			j += ", \"ms_candidates\": " + jsonNumber(c.msCandidates);
			j += ", \"ms_nms\": " + jsonNumber(c.msNms);
			j += ", \"ms_other\": " + jsonNumber(c.msOther());
			j += ", \"ms_decode\": " + jsonNumber(c.msDecode);
			j += ", \"wall_s\": " + jsonNumber(c.wallSeconds);
			j += ", \"peak_rss_kib\": " + std::to_string(c.peakRssKib);
		} else {
			j += ",\n   \"scales\": null, \"octaves\": null, \"capf\": null, \"ms_per_frame\": null, "
			     "\"peak_rss_kib\": null";
		}
		j += "}";
	}
	j += runs.empty() ? "]\n" : "\n]\n";
	return j;
}

} // namespace calped::eval_tool
