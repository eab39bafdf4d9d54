// SPDX-License-Identifier: BSD-2-Clause
// Which ground-truth pedestrians the generic mode finds and the calibrated mode misses, and
// why (issue 16, item 4). Runs on every frame the generic method, the calibrated method as
// configured, and the calibrated method with one mechanism taken away at a time; a person
// is "found" by a run when one of its detections overlaps the box at IoU >= 0.5 (the
// thesis's criterion; every detection counts, whatever its score). Each person the generic
// mode finds and the calibrated mode misses gets the first cause that applies:
//   cut off      the box leaves the frame (feet below the bottom edge, or a side)
//   height       its world height is outside the configured plausible range
//   sparse grid  found when every plausible window is evaluated (no sparse/dense phases)
//   levels       found with the toolbox's octaves instead of placed levels
//   suppression  found when no window is suppressed
//   other        none of these recovers it
// Usage:
//   recall_causes --frames DIR --gt FILE --model BLOB --calib FILE [--resize R]
//                 [--min-height H] [--max-height H] [--persistence N] [--score-ratio]
//                 [--no-box-voting] [--max-frames N] [--list]
// The height, persistence and suppression flags set the calibrated runs' settings.
// --list prints each missed person (frame, box, world height, cause).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "boxes.h"
#include "frame_source.h"
#include "ground_truth.h"
#include "image_io.h"
#include "program.h"

using namespace calped;
using namespace calped::eval_tool;

namespace {

struct Run {
	const char *name;
	DetectorConfig config;
	std::unique_ptr<Detector> detector;
	long found = 0;
	uint64_t windows = 0;
};

enum Cause { CutOff, Height, SparseGrid, Levels, Suppression, Other, CauseCount };
const char *const kCauseNames[CauseCount] = { "cut off by the frame", "outside the height range",
					       "sparse grid, no dense region", "placed levels",
					       "suppression", "other" };

bool foundBy(const Detections &d, const Box &truth)
{
	for (const Detection &x : d) {
		const Box b{ x.x, x.y, x.w, x.h };
		if (intersectionOverUnion(b, truth) >= 0.5)
			return true;
	}
	return false;
}

// Models and calibrations, both under the model cap (the larger of the two; docs/errors.md).
bool readAll(const std::string &path, std::vector<uint8_t> &out, const char *what)
{
	std::string error;
	if (!ports::readFileBytes(path, out, error, what, ports::kMaxModelFileBytes)) {
		std::fprintf(stderr, "recall_causes: %s\n", error.c_str());
		return false;
	}
	return true;
}

const apps::ProgramInfo kProgram = {
	"recall_causes",
	"usage: recall_causes --frames DIR --gt FILE --model BLOB --calib FILE [options]\n"
	"\n"
	"Why the calibrated method misses people the generic mode finds, person by person\n"
	"(docs/calibrated.md).\n"
	"\n"
	"options:\n",
	"",
};

} // namespace

int main(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> table = {
		{ "frames", "DIR", "the PNG frames, in name order" },
		{ "gt", "FILE", "ground truth (PETS CVML or MOT)" },
		{ "model", "BLOB", "calped model blob (.cpm)" },
		{ "calib", "FILE", "camera calibration" },
		{ "resize", "R", "upscale by R, 0 < R <= 8 (default 2)" },
		{ "min-height", "H", "plausible person heights from H metres (default the detector's)" },
		{ "max-height", "H", "... up to H metres (default the detector's)" },
		{ "persistence", "N", "frames a dense region lives (default the detector's)" },
		{ "score-ratio", nullptr, "the score-ratio step on" },
		{ "no-box-voting", nullptr, "box voting off" },
		{ "max-frames", "N", "only the first N frames" },
		{ "list", nullptr, "print every missed person" },
	};
	apps::ParsedArgs args;
	const int rc = apps::parseCommandLine(kProgram, table, false, argc, argv, args);
	if (rc >= 0)
		return rc;
	std::string framesDir, gtPath, modelPath, calibPath, error;
	double resize = 2.0, minHeight = CalibratedSettings().minPersonHeight,
	       maxHeight = CalibratedSettings().maxPersonHeight;
	long maxFrames = 0, persistence = 0;
	bool list = false;
	CalibratedSettings plan;
	for (const apps::ParsedOption &o : args.options) {
		if (o.name == "list")
			list = true;
		else if (o.name == "frames")
			apps::nonEmpty(o, "a folder", framesDir, error);
		else if (o.name == "gt")
			apps::nonEmpty(o, "a file name", gtPath, error);
		else if (o.name == "model")
			apps::nonEmpty(o, "a file name", modelPath, error);
		else if (o.name == "calib")
			apps::nonEmpty(o, "a file name", calibPath, error);
		else if (o.name == "resize")
			apps::numberIn(o, 0, true, 8, resize, error);
		else if (o.name == "min-height")
			apps::numberIn(o, 0, true, 10, minHeight, error);
		else if (o.name == "max-height")
			apps::numberIn(o, 0, true, 10, maxHeight, error);
		else if (o.name == "persistence" && apps::wholeIn(o, 0, 1000000, persistence, error))
			plan.denseRegionPersistence = int(persistence);
		else if (o.name == "score-ratio")
			plan.scoreRatio = true;
		else if (o.name == "no-box-voting")
			plan.boxVoting = false;
		else if (o.name == "max-frames")
			apps::wholeIn(o, 1, 1000000000, maxFrames, error);
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (framesDir.empty() || gtPath.empty() || modelPath.empty() || calibPath.empty())
		return apps::usageError(kProgram, "needs --frames, --gt, --model and --calib (try --help)");

	std::vector<uint8_t> bytes;
	Model model;
	CameraModel camera;
	if (!readAll(modelPath, bytes, "model "))
		return 1;
	if (Status st = loadModel(bytes.data(), bytes.size(), model); !st.ok()) {
		std::fprintf(stderr, "recall_causes: %s: %s\n", modelPath.c_str(), st.message());
		return 1;
	}
	if (!readAll(calibPath, bytes, "calibration "))
		return 1;
	if (Status st = loadCalibration(reinterpret_cast<const char *>(bytes.data()), bytes.size(),
					calibPath.c_str(), camera);
	    !st.ok()) {
		std::fprintf(stderr, "recall_causes: %s\n", st.message());
		return 1;
	}
	GroundTruth truth;
	FrameInput input;
	if (!loadGroundTruth(gtPath, truth, error) ||
	    !resolveFolderInput(framesDir, maxFrames, input, error)) {
		std::fprintf(stderr, "recall_causes: %s\n", error.c_str());
		return 1;
	}

	DetectorConfig base;
	base.maxWidth = input.width;
	base.maxHeight = input.height;
	base.resize = resize;
	base.camera = &camera;
	plan.minPersonHeight = minHeight;
	plan.maxPersonHeight = maxHeight;
	base.calibrated = plan;

	std::vector<Run> runs(CauseCount);
	runs[0] = { "generic", base, nullptr };
	runs[0].config.method = DetectionMethod::Generic;
	runs[0].config.calibrated.reset();
	runs[1] = { "calibrated", base, nullptr };
	runs[2] = { "calibrated, every plausible window", base, nullptr };
	runs[2].config.calibrated->sparseDense = false;
	runs[3] = { "calibrated, toolbox octaves", base, nullptr };
	runs[3].config.calibrated->levels = PyramidLevels::Toolbox;
	runs[4] = { "calibrated, no suppression", base, nullptr };
	runs[4].config.nms = false;
	runs[4].config.calibrated->scoreRatio = false;
	runs[4].config.calibrated->boxVoting = false;
	runs[4].config.maxCandidates = 1 << 22;
	runs.resize(5);
	for (Run &r : runs) {
		if (Status st = Detector::create(model, r.config, r.detector); !st.ok()) {
			std::fprintf(stderr, "recall_causes: %s: %s\n", r.name, st.message());
			return 1;
		}
	}

	std::unique_ptr<FrameSource> source = input.open(error);
	if (!source) {
		std::fprintf(stderr, "recall_causes: %s\n", error.c_str());
		return 1;
	}
	long causes[CauseCount] = {};
	long people = 0, frames = 0;
	RgbImage image;
	std::vector<Detections> found(runs.size());
	while (source->next(image, error)) {
		++frames;
		const ImageView view = ImageView::rgb8(image.pixels.data(), image.width, image.height);
		for (size_t i = 0; i < runs.size(); ++i) {
			if (Status st = runs[i].detector->detect(view, found[i]); !st.ok()) {
				std::fprintf(stderr, "recall_causes: frame %ld: %s\n", frames, st.message());
				return 1;
			}
			runs[i].windows += runs[i].detector->lastStats().windows;
		}
		for (const GtBox &g : truth.boxes(frames)) {
			if (g.ignore)
				continue;
			++people;
			bool by[5];
			for (size_t i = 0; i < runs.size(); ++i) {
				by[i] = foundBy(found[i], g.box);
				runs[i].found += by[i];
			}
			if (!by[0] || by[1])
				continue;
			const Box &b = g.box;
			const Eigen::Vector2d foot(b.x + b.w / 2, b.y + b.h), head(b.x + b.w / 2, b.y);
			const double height = camera.boxWorldHeight(foot, head);
			Cause c = Other;
			if (b.x < 0 || b.y < 0 || b.x + b.w > image.width || b.y + b.h > image.height)
				c = CutOff;
			else if (!(height >= minHeight && height <= maxHeight))
				c = Height;
			else if (by[2])
				c = SparseGrid;
			else if (by[3])
				c = Levels;
			else if (by[4])
				c = Suppression;
			++causes[c];
			if (list)
				std::printf("frame %ld box %.0f,%.0f,%.0fx%.0f height %.2f m: %s\n", frames,
					    b.x, b.y, b.w, b.h, height, kCauseNames[c]);
		}
	}
	if (!error.empty()) {
		std::fprintf(stderr, "recall_causes: %s\n", error.c_str());
		return 1;
	}

	std::printf("frames %ld, ground-truth people %ld, resize %.2f, heights %.2f-%.2f m\n", frames,
		    people, resize, minHeight, maxHeight);
	std::printf("\n| run | found (any detection at IoU >= 0.5) | windows per frame |\n"
		    "|---|---:|---:|\n");
	for (const Run &r : runs)
		std::printf("| %s | %ld (%.3f) | %.0f |\n", r.name, r.found,
			    people ? double(r.found) / people : 0.0,
			    frames ? double(r.windows) / frames : 0.0);
	long missed = 0;
	for (long c : causes)
		missed += c;
	std::printf("\nfound by generic, missed by calibrated: %ld\n\n| cause | people |\n|---|---:|\n",
		    missed);
	for (int c = 0; c < CauseCount; ++c)
		std::printf("| %s | %ld |\n", kCauseNames[c], causes[c]);
	return 0;
}
