// SPDX-License-Identifier: BSD-2-Clause
// The ACF pedestrian detector, generic mode (Dollár's sliding window over the fast
// feature pyramid). All memory is allocated by create(); detect() allocates nothing.
#pragma once

#include <cstdint>
#include <memory>

#include <calped/image.h>
#include <calped/model.h>
#include <calped/status.h>

namespace calped {

class CameraModel;

// Generic: Dollár's detector, every window of every pyramid level. Calibrated: the
// thesis's method (chapter 3): only pyramid levels and windows where a person of
// plausible world height can stand, given the camera's calibration.
enum class DetectionMethod { Generic, Calibrated };

// Beyond the thesis, for fixed cameras: drop detections on static scene structure (a
// tripod, a sign or a post that looks like a person and is found in the same place frame
// after frame). The detector keeps a background of the frame's 4x4-pixel grey cells as
// an approximate running median (every frame moves each cell one grey level towards what
// it sees) and drops a detection whose box has fewer than minForeground of its cells
// differing from it by more than `difference` grey levels. A person who stands still
// long enough fades into that background too (at one grey level per frame); the
// background starts again when the frame size changes. In the calibrated mode with
// sparse and dense windows, `gateSparse` also skips, once the background is ready, the
// sparse windows whose own box has fewer than minForeground of its cells differing:
// what they could find there would be dropped anyway, and the pyramid is then only
// needed where something moves. docs/calibrated.md.
struct StaticRejection {
	bool enabled = false;
	int difference = 10;        // grey levels, 1..254
	float minForeground = 0.1f; // fraction of the box's cells, 0..1
	int warmupFrames = 50;      // first frames of a background, none dropped (>= 1)
	bool gateSparse = true;     // calibrated mode: no sparse windows on static scene
};

struct DetectorConfig {
	// Largest input frame (before resizing) that detect() will accept.
	int maxWidth = 1920;
	int maxHeight = 1080;
	// Input upscaling factor (the thesis's "resize"): the frame is resampled to
	// round(size * resize) first, as the toolbox's imResample does; boxes come back in
	// input pixels. 1.0 means no resampling.
	double resize = 1.0;
	// Do the resize inside the feature pyramid instead (needs resize >= 1): colour is
	// converted at the input size and every computed level is resampled from it, as the
	// toolbox does with nOctUp (resize 2 here is its nOctUp = 1 exactly). No upscaled
	// frame is made and the colour conversion covers 1/resize^2 of the pixels, so it is
	// faster; the channels differ slightly from the resized frame's (colour conversion
	// and resampling in the other order). docs/calibrated.md has both measured.
	bool resizeInPyramid = false;
	// Capacity for windows that pass the cascade in one frame (before NMS). Excess windows
	// are dropped and counted in FrameStats::droppedWindows, never silently lost.
	int maxCandidates = 1 << 16;
	// Override the model's cascade threshold (NaN keeps the model's).
	float cascadeThreshold = __builtin_nanf("");
	// Skip non-maximum suppression (returns every window that passed the cascade).
	bool disableNms = false;

	// A camera (copied by create()) gives detections their ground position and world
	// height, and is required by calibrated mode. Its pixels are the input frame's (before
	// resize): every frame must then be exactly maxWidth x maxHeight.
	DetectionMethod method = DetectionMethod::Generic;
	const CameraModel *camera = nullptr;
	// Plausible pedestrian heights, metres (calibrated mode).
	double minPersonHeight = 1.4;
	double maxPersonHeight = 2.2;
	// Thesis 3.2: a sparse grid of windows first, then every window in dense regions around
	// its detections. false evaluates every plausible window instead.
	bool sparseDense = true;
	// Thesis 3.4: a dense region is removed after this many frames in a row without a
	// detection inside (1 reproduces the thesis).
	int denseRegionPersistence = 1;
	// Capacity for dense regions; regions beyond it are not created, and counted.
	int maxDenseRegions = 256;
	// Calibrated mode, beyond the thesis: after suppression, each box moves to the
	// score^4-weighted mean of the windows overlapping it (IoU > 0.6), which places it
	// better than the single best window (docs/calibrated.md). Off: the thesis's boxes.
	bool boxVoting = true;
	// Calibrated mode, beyond the thesis and the toolbox: compute channels at pyramid
	// levels chosen among the needed ones instead of at octaves of the frame, each
	// approximated level at most placedLevelReach levels from its computed level, placed
	// where the row bands cost the fewest pixels. Much less work when the needed levels
	// start below an octave; the detections differ slightly from the toolbox pyramid's.
	// Calibrated method only, and no frame resize first (resize 1 or resizeInPyramid).
	// docs/calibrated.md.
	bool calibratedPyramid = false;
	// How far approximations may reach with calibratedPyramid, in pyramid levels (1..16;
	// 5 is 5/8 of an octave for the INRIA model, whose toolbox pyramid reaches 4 down and 3
	// up; measured in docs/calibrated.md).
	int placedLevelReach = 5;
	// Either method: drop detections on static scene structure (off by default).
	StaticRejection staticRejection;
};

// One detection in input-image pixels: top-left corner, size, classifier score. With a
// calibration, also where the person stands on the ground (metres, world x and y) and
// the box's world height (metres); NaN without one, or when the foot is above the horizon.
struct Detection {
	float x = 0, y = 0, w = 0, h = 0;
	float score = 0;
	float groundX = __builtin_nanf(""), groundY = __builtin_nanf(""), worldHeight = __builtin_nanf("");
};

// What the detector did on the last frame (counters come from the detector itself).
struct FrameStats {
	int levels = 0;          // pyramid levels used
	int computedLevels = 0;  // levels whose channels were computed (octaves)
	uint64_t windows = 0;    // classifier windows evaluated (CApF)
	uint64_t candidates = 0; // windows that passed the cascade
	uint64_t droppedWindows = 0;
	// Calibrated mode: windows of the sparse grid and of dense regions, regions alive after
	// this frame, regions not created for lack of capacity (since create()).
	uint64_t sparseWindows = 0, denseWindows = 0;
	int denseRegions = 0;
	uint64_t droppedRegions = 0;
	// Detections dropped as static scene structure, and sparse windows not evaluated
	// because their box is static scene (DetectorConfig::staticRejection).
	int staticRejected = 0;
	uint64_t staticSkipped = 0;
	// Wall time per stage: input resize, channels of computed levels, approximated levels
	// (with smoothing and padding), classification, calibrated candidate generation and
	// dense-region upkeep, suppression, and the whole frame.
	double msResize = 0, msChannels = 0, msApprox = 0, msClassify = 0, msCandidates = 0,
	       msNms = 0, msTotal = 0;
};

// Result of one call: valid until the next detect() on the same detector.
struct Detections {
	const Detection *items = nullptr;
	int count = 0;
	const Detection *begin() const { return items; }
	const Detection *end() const { return items + count; }
};

class DetectorImpl;

class Detector
{
public:
	// Allocates every buffer the largest configured frame needs.
	static Status create(const Model &model, const DetectorConfig &config,
			     std::unique_ptr<Detector> &out);
	~Detector();

	// Runs the detector on one frame in any PixelFormat (converted to RGB in integer
	// arithmetic, docs/pixel-formats.md). Frames may differ in size and format between
	// calls as long as they fit the configured maximum.
	Status detect(const ImageView &image, Detections &out);

	const FrameStats &lastStats() const;
	const DetectorConfig &config() const;

	// Internal access for tests and tools that inspect the pyramid.
	DetectorImpl &impl() { return *impl_; }

private:
	Detector() = default;
	std::unique_ptr<DetectorImpl> impl_;
};

} // namespace calped
