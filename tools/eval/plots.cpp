// SPDX-License-Identifier: BSD-2-Clause
#include "plots.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "external_tools.h"
#include "overlay_frames.h"
#include "report.h"

namespace calped::eval_tool {

namespace {

std::string num(double v)
{
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.9g", v);
	return buf;
}

// Gnuplot string literal in single quotes ('' stands for one quote).
std::string gpQuote(const std::string &s)
{
	std::string out = "'";
	for (char c : s)
		out += c == '\'' ? std::string("''") : std::string(1, c);
	return out + "'";
}

std::string groupName(const RunResult &r)
{
	return r.resize > 0 ? "r" + resizeLabel(r.resize) : "scored";
}

constexpr double kMinFppf = 1e-3; // left edge of the TPR-vs-FPPF plots

const char *kTerminal = "set terminal pngcairo size 900,640 font 'DejaVu Sans,11'\n";

} // namespace

bool writePlots(const std::string &dir, const std::vector<RunResult> &runs,
		std::vector<std::string> &images, std::string &notice, std::string &error)
{
	std::vector<std::string> scripts; // file names inside dir

	// TPR vs FPPF, one plot per resize. Points at FPPF 0 cannot sit on a log axis.
	std::map<std::string, std::vector<const RunResult *>> groups;
	for (const RunResult &r : runs)
		groups[groupName(r)].push_back(&r);
	for (const auto &g : groups) {
		double maxFppf = 1.0;
		std::string plot;
		for (const RunResult *r : g.second) {
			const std::string dat = "curve_" + (r->resize > 0 ? runStem(r->method, r->resize)
								     : r->method) + ".dat";
			std::string text = "# fppf tpr score (" + r->method + "; keep detections with score >= score)\n";
			const std::vector<CurvePoint> &curve = r->evaluation.curve;
			for (size_t i = 0; i < curve.size(); i++) {
				const CurvePoint &p = curve[i];
				// FPPF 0 has no place on a log axis: the best point without a false
				// positive is drawn at the axis's left edge, the rest are left out.
				const bool lastAtZero = p.fppf <= 0 && (i + 1 == curve.size() || curve[i + 1].fppf > 0);
				if (p.fppf <= 0 && !lastAtZero)
					continue;
				text += (p.fppf > 0 ? num(p.fppf) : num(kMinFppf)) + " " + num(p.tpr) + " " +
					num(p.score) + "\n";
				maxFppf = std::max(maxFppf, p.fppf);
			}
			if (!writeTextFile(dir + "/" + dat, text, error))
				return false;
			char title[160];
			std::snprintf(title, sizeof(title), "%s (TPR %.3f at %.2f FPPF, LAMR %.3f)",
				      r->method.c_str(), r->evaluation.tpr, r->evaluation.fppf,
				      r->evaluation.logAverageMissRate);
			plot += (plot.empty() ? "plot " : ", \\\n     ") + gpQuote(dat) +
				" using 1:2 with steps lw 2 title " + gpQuote(title);
		}
		const std::string png = "tpr_fppf_" + g.first + ".png";
		const std::string title = g.first == "scored" ? std::string("TPR vs FPPF")
							      : "TPR vs FPPF, resize " + g.first.substr(1);
		std::string gp = kTerminal;
		gp += "set output " + gpQuote(png) + "\n";
		gp += "set title " + gpQuote(title) + "\n";
		gp += "set logscale x\nset xrange [" + num(kMinFppf) + ":" + num(maxFppf * 1.2) + "]\nset yrange [0:1]\n";
		gp += "set xlabel 'false positives per frame (FPPF)'\nset ylabel 'true positive rate (TPR)'\n";
		gp += "set grid xtics ytics mxtics\nset key top left\n";
		// The log-average miss rate is taken between these two lines.
		gp += "set arrow from 1e-2, graph 0 to 1e-2, graph 1 nohead dt 3 lc 'gray'\n";
		gp += "set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc 'gray'\n";
		gp += plot + "\n";
		const std::string script = "tpr_fppf_" + g.first + ".gp";
		if (!writeTextFile(dir + "/" + script, gp, error))
			return false;
		scripts.push_back(script);
		images.push_back(dir + "/" + png);
	}

	// Stage times: one stacked bar per run with counters.
	std::string dat = "# run resize channels approximated classification candidates suppression other "
			  "(ms/frame)\n";
	int bars = 0;
	for (const RunResult &r : runs) {
		if (!r.hasCounters)
			continue;
		const RunCounters &c = r.counters;
		dat += "\"" + r.method + " " + resizeLabel(r.resize) + "\" " + num(c.msResize) + " " +
		       num(c.msChannels) + " " + num(c.msApprox) + " " + num(c.msClassify) + " " +
		       num(c.msCandidates) + " " + num(c.msNms) + " " + num(c.msOther()) + "\n";
		bars++;
	}
	if (bars > 0) {
		if (!writeTextFile(dir + "/stage_times.dat", dat, error))
			return false;
		std::string gp = kTerminal;
		gp += "set output 'stage_times.png'\n";
		gp += "set title 'Detector time per frame by stage'\nset ylabel 'ms per frame'\n";
		gp += "set style data histograms\nset style histogram rowstacked\n";
		gp += "set style fill solid 0.85 border -1\nset boxwidth 0.6\nset key outside right top\n";
		gp += "set yrange [0:*]\nset grid ytics\nset xtics rotate by 30 right\n";
		static const char *const kStages[] = { "resize", "channels (octaves)", "approximated levels",
						       "classification", "candidates", "suppression", "other" };
		gp += "plot ";
		for (int s = 0; s < 7; s++)
			gp += std::string(s ? ", \\\n     " : "") + "'stage_times.dat' using " +
			      std::to_string(s + 2) + (s == 0 ? ":xtic(1)" : "") + " title " +
			      gpQuote(kStages[s]);
		gp += "\n";
		if (!writeTextFile(dir + "/stage_times.gp", gp, error))
			return false;
		scripts.push_back("stage_times.gp");
		images.push_back(dir + "/stage_times.png");
	}

	if (!findExecutable("gnuplot")) {
		notice = "gnuplot not found: plots skipped, their data and scripts are in " + dir +
			 " (Debian: apt-get install gnuplot-nox)";
		images.clear();
		return true;
	}
	for (const std::string &script : scripts) {
		std::string out;
		if (!runCapture("cd " + shellQuote(dir) + " && gnuplot " + shellQuote(script) + " 2>&1",
				out, error)) {
			error = "gnuplot could not draw " + dir + "/" + script + ": " + error +
				(out.empty() ? "" : ": " + out.substr(0, 300));
			return false;
		}
	}
	return true;
}

} // namespace calped::eval_tool
