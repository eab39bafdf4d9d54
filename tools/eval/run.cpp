// SPDX-License-Identifier: BSD-2-Clause
#include "run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "dets_csv.h"
#include "file_io.h"
#include "json_frame.h"
#include "writers.h"
#include "overlay_frames.h"
#include "stop_signal.h"

namespace calped::eval_tool {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t)
{
	return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

std::string overlayPath(const RunSettings &s, const std::string &stem, long frame)
{
	return s.overlayDir + "/" + stem + "/" + apps::overlayFileName(frame);
}

} // namespace

double RunCounters::msOther() const
{
	return std::max(0.0, msTotal - (msResize + msChannels + msApprox + msClassify +
					 msCandidates + msNms));
}

bool runMethod(const MethodEntry &entry, double resize, const RunSettings &s, RunResult &out,
	       std::string &error)
{
	out = RunResult();
	out.method = entry.name;
	out.resize = resize;
	out.hasCounters = true;
	const std::string stem = runStem(entry.name, resize);
	const Clock::time_point start = Clock::now();

	MethodSetup setup;
	setup.model = s.model;
	setup.options = s.options;
	setup.options.resize = resize;
	setup.maxWidth = s.input->width;
	setup.maxHeight = s.input->height;
	std::unique_ptr<Method> method;
	if (!entry.create(setup, method, error))
		return false;
	std::unique_ptr<FrameSource> source = s.input->open(error);
	if (!source)
		return false;
	if (!s.overlayDir.empty() && !apps::makeDirectories(s.overlayDir + "/" + stem, error))
		return false;
	apps::OutputFile jsonl;
	if (!s.framesJsonlDir.empty() && !jsonl.open(s.framesJsonlDir + "/" + stem + ".jsonl", error))
		return false;

	RunCounters &c = out.counters;
	std::vector<double> totals;
	double sumLevels = 0, sumOctaves = 0, sumWindows = 0, sumCandidates = 0, sumDecode = 0;
	RgbImage image;
	Clock::time_point lastProgress = start;
	for (long frame = 1;; frame++) {
		if (apps::stopRequested())
			break; // the frames so far keep their complete JSON lines
		const Clock::time_point t0 = Clock::now();
		if (!source->next(image, error)) {
			if (!error.empty())
				return false;
			break;
		}
		sumDecode += msSince(t0);

		Detections dets;
		Status st = method->detect(ImageView::rgb8(image.pixels.data(), image.width, image.height),
					   dets);
		std::vector<ScoredBox> boxes;
		if (st.code() == ErrorCode::ImageTooSmall) {
			// No window fits: the honest answer is "nobody", as in calped-detect.
			c.tooSmall++;
		} else if (!st.ok()) {
			error = s.input->label(frame) + ": " + st.message();
			return false;
		} else {
			const FrameStats &fs = method->lastStats();
			if (c.frames == 0) {
				c.levelsMin = c.levelsMax = fs.levels;
				c.octavesMin = c.octavesMax = fs.computedLevels;
			}
			c.levelsMin = std::min(c.levelsMin, fs.levels);
			c.levelsMax = std::max(c.levelsMax, fs.levels);
			c.octavesMin = std::min(c.octavesMin, fs.computedLevels);
			c.octavesMax = std::max(c.octavesMax, fs.computedLevels);
			sumLevels += fs.levels;
			sumOctaves += fs.computedLevels;
			sumWindows += static_cast<double>(fs.windows);
			sumCandidates += static_cast<double>(fs.candidates);
			c.droppedWindows += fs.droppedWindows;
			c.msResize += fs.msResize;
			c.msChannels += fs.msChannels;
			c.msApprox += fs.msApprox;
			c.msClassify += fs.msClassify;
			c.msCandidates += fs.msCandidates;
			c.msNms += fs.msNms;
			c.msTotal += fs.msTotal;
			totals.push_back(fs.msTotal);
			c.frames++;
			boxes.reserve(static_cast<size_t>(dets.count));
			for (const Detection &d : dets)
				boxes.push_back({ Box{ floatAsDecimal(d.x), floatAsDecimal(d.y),
						       floatAsDecimal(d.w), floatAsDecimal(d.h) },
						  floatAsDecimal(d.score) });
		}

		if (!s.overlayDir.empty() &&
		    std::find(s.overlayFrames.begin(), s.overlayFrames.end(), frame) != s.overlayFrames.end()) {
			const RgbImage overlay = renderEvaluationOverlay(image, s.truth->boxes(frame), boxes,
									 s.overlayScore);
			if (!ports::writePng(overlayPath(s, stem, frame), overlay, error))
				return false;
		}
		if (jsonl.isOpen()) {
			apps::JsonFrame record;
			record.frame = frame;
			record.method = entry.name;
			const std::string file = s.input->file(frame);
			record.file = file.c_str();
			record.width = image.width;
			record.height = image.height;
			record.ms = st.ok() ? method->lastStats().msTotal : 0.0;
			writeJsonFrame(jsonl.get(), record, st.ok() ? dets : Detections());
		}
		out.detections.push_back(std::move(boxes));
		out.frames = frame;

		if (!s.quiet && msSince(lastProgress) > 5000) {
			lastProgress = Clock::now();
			const long known = s.input->knownFrames();
			std::fprintf(stderr, "calped-eval: %s: %ld%s frames, detector %.1f ms/frame\n",
				     stem.c_str(), frame,
				     known > 0 ? ("/" + std::to_string(known)).c_str() : "",
				     c.frames ? c.msTotal / c.frames : 0.0);
		}
	}
	if (!jsonl.close(error))
		return false;
	if (apps::stopRequested()) {
		error = "stopped by a signal after frame " + std::to_string(out.frames);
		return false;
	}
	if (out.frames == 0) {
		error = "no frames to process";
		return false;
	}

	if (c.frames > 0) {
		const double n = static_cast<double>(c.frames);
		c.levelsMean = sumLevels / n;
		c.octavesMean = sumOctaves / n;
		c.windowsMean = sumWindows / n;
		c.candidatesMean = sumCandidates / n;
		c.msResize /= n;
		c.msChannels /= n;
		c.msApprox /= n;
		c.msClassify /= n;
		c.msCandidates /= n;
		c.msNms /= n;
		c.msTotal /= n;
		std::sort(totals.begin(), totals.end());
		const size_t m = totals.size() / 2;
		c.msTotalMedian = totals.size() % 2 ? totals[m] : (totals[m - 1] + totals[m]) / 2;
	}
	c.msDecode = sumDecode / static_cast<double>(out.frames);
	c.wallSeconds = msSince(start) / 1000.0;
	return true;
}

} // namespace calped::eval_tool
