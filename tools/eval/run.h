// SPDX-License-Identifier: BSD-2-Clause
// One run: one method at one resize over the whole frame sequence, collecting the
// detections and the detector's own counters.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "boxes.h"
#include "frame_source.h"
#include "ground_truth.h"
#include "methods.h"
#include "metrics.h"

namespace calped::eval_tool {

// Means are per frame the detector ran on. Plain data: runs in child processes send it
// back to the harness as bytes.
struct RunCounters {
	long frames = 0;       // frames the detector ran on
	long tooSmall = 0;     // frames smaller than the model window (no detections)
	int levelsMin = 0, levelsMax = 0;
	int octavesMin = 0, octavesMax = 0;
	double levelsMean = 0, octavesMean = 0;
	double windowsMean = 0;    // CApF
	double candidatesMean = 0; // windows that passed the cascade, before suppression
	uint64_t droppedWindows = 0;
	double msResize = 0, msChannels = 0, msApprox = 0, msClassify = 0, msCandidates = 0,
	       msNms = 0;
	double msTotal = 0;       // mean FrameStats::msTotal
	double msTotalMedian = 0;
	double msDecode = 0;      // mean time to get a frame (image decoding or the ffmpeg pipe)
	double wallSeconds = 0;   // the whole run, decoding and overlays included
	long peakRssKib = 0;      // getrusage ru_maxrss of the run's process

	// Time the detector spent outside the named stages.
	double msOther() const;
};

// The result of a run, or of scoring a detection file (then without counters).
struct RunResult {
	std::string method;
	double resize = 0;       // 0 when unknown (a scored file whose name does not say)
	bool hasCounters = false;
	RunCounters counters;
	long frames = 0;         // frames processed = frames scored
	SequenceDetections detections;
	Evaluation evaluation;
};

struct RunSettings {
	const FrameInput *input = nullptr;
	const Model *model = nullptr;
	apps::DetectorOptions options; // --calib, --resize-at, --levels; the resize is the run's
	std::string framesJsonlDir;    // empty = none
	// Overlays: written by the run itself, which holds the frames.
	const GroundTruth *truth = nullptr;
	std::string overlayDir; // empty = none
	std::vector<long> overlayFrames;
	double overlayScore = 0;
	bool quiet = false;
};

// Runs in the calling process; fills everything but `evaluation` and `peakRssKib`.
bool runMethod(const MethodEntry &method, double resize, const RunSettings &settings,
	       RunResult &out, std::string &error);

} // namespace calped::eval_tool
