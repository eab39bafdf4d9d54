// SPDX-License-Identifier: BSD-2-Clause
// The ACF pedestrian detector: Dollár's sliding window over the fast feature pyramid
// (generic method) or the thesis's calibrated method. All memory is allocated by
// create(); detect() allocates nothing.
//
// Threads: a Detector may use several threads itself (DetectorConfig::threads: a pool
// made by create(), internal to the detector; its output is byte-identical for any
// number). A Detector is not thread-safe: call one Detector's methods from one thread at a
// time (detect(), lastStats() and the Detections it returned are its own state, with its
// buffers and static background). Separate Detectors are independent: each may run on its
// own thread, concurrently, and they may share one Model (and one CameraModel): create()
// only reads them and copies what it needs, so several threads may create detectors from
// one Model at once, and the Model may be freed afterwards (it must not be modified while
// a create() reads it). Results are identical to running the same detectors one after the
// other (tests/core/detectors_on_threads_test.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <calped/image.h>
#include <calped/model.h>
#include <calped/status.h>

namespace calped {

class CameraModel;

// Generic: Dollár's detector, every window of every pyramid level. Calibrated: the
// thesis's method (chapter 3): only pyramid levels and windows where a person of
// plausible world height can stand, given the camera's calibration. Auto, the default:
// calibrated when the configuration has a camera, generic without one.
enum class DetectionMethod { Auto, Generic, Calibrated };

// Where the input resize happens. Pyramid, the default: colour is converted at the input
// size and every computed level is resampled from it, as the toolbox does with nOctUp
// (resize 2 is its nOctUp = 1 exactly); no upscaled frame is made, and it is faster. Frame:
// the frame itself is resampled first, as the toolbox's imResample and the thesis do; the
// only choice for resizes below 1. The channels of the two differ slightly (colour
// conversion and resampling in the other order); docs/calibrated.md has both measured.
enum class ResizeAt { Pyramid, Frame };

// Which pyramid levels have their channels computed (the others are approximated from
// the nearest computed one). Toolbox: one per octave of the frame, as Dollár's toolbox.
// Placed (calibrated method only, the default there): levels chosen among those the
// camera needs, each approximated level at most placedLevelReach levels from its
// computed one, placed where the computed rows cost least; much less work when the
// needed levels start below an octave, detections slightly different.
enum class PyramidLevels { Placed, Toolbox };

// The calibrated method's settings (thesis chapter 3, and what calped adds).
struct CalibratedSettings {
	// Plausible pedestrian heights, metres: 0 < min <= max < 10.
	double minPersonHeight = 1.4;
	double maxPersonHeight = 2.2;
	// Thesis 3.2: a sparse grid of windows first, then every window in dense regions
	// around its detections. false evaluates every plausible window instead.
	bool sparseDense = true;
	// Thesis 3.4 (sparseDense): a dense region is removed after this many frames in a row
	// without a detection inside (1 reproduces the thesis; more keeps a person whom the
	// sparse grid misses for a frame or two, docs/calibrated.md); at most maxDenseRegions
	// regions, those beyond are not created and are counted (FrameStats).
	int denseRegionPersistence = 3;
	int maxDenseRegions = 256;
	// Thesis 3.3, the second suppression step: after NMS, a box overlapping a better one
	// by more than the ratio of their scores is dropped. Off by default: it also drops
	// people partly hidden by a better-scoring neighbour (docs/calibrated.md).
	bool scoreRatio = false;
	// Beyond the thesis: after suppression, each box moves to the score^4-weighted mean of
	// the windows overlapping it (IoU > 0.6), which places it better than the single best
	// window (docs/calibrated.md). false: the thesis's boxes.
	bool boxVoting = true;
	PyramidLevels levels = PyramidLevels::Placed;
	// Placed levels: how far approximations may reach, in pyramid levels (1..16; 5 is 5/8
	// of an octave for the INRIA model, whose toolbox pyramid reaches 4 down and 3 up).
	int placedLevelReach = 5;
};

// Beyond the thesis, for fixed cameras: drop detections on static scene structure (a
// tripod, a sign or a post that looks like a person and is found in the same place frame
// after frame). The detector keeps a background of the frame's 4x4-pixel grey cells as
// an approximate running median (every frame moves each cell one grey level towards what
// it sees) and drops a detection whose box has fewer than minForeground of its cells
// differing from it by more than `difference` grey levels. A person who stands still
// long enough fades into that background too (at one grey level per frame); the
// background starts again when the frame size changes. With the calibrated method's
// sparse grid, the same test also skips, once the background is ready, the sparse
// windows whose own box is static: what they could find there would be dropped anyway,
// and the pyramid is then only needed where something moves. docs/calibrated.md.
struct StaticRejection {
	int difference = 10;        // grey levels, 1..254
	float minForeground = 0.1f; // fraction of the box's cells, 0..1
	int warmupFrames = 50;      // first frames of a background, none dropped (>= 1)
};

struct DetectorConfig {
	// Largest input frame (before resizing) that detect() will accept, 1..16384.
	int maxWidth = 1920;
	int maxHeight = 1080;
	// Input scaling factor (the thesis's "resize", 0 < resize <= 8): detection runs on
	// the frame as if resized to round(size * resize); boxes come back in input pixels.
	double resize = 1.0;
	ResizeAt resizeAt = ResizeAt::Pyramid;
	// Capacity for windows that pass the cascade in one frame (before NMS), 1..2^24.
	// Excess windows are dropped and counted in FrameStats::droppedWindows.
	int maxCandidates = 1 << 16;
	// Override the model's cascade threshold (NaN keeps the model's).
	float cascadeThreshold = __builtin_nanf("");
	// Non-maximum suppression. false returns every window that passed the cascade (then
	// the calibrated method's scoreRatio and boxVoting must be off too).
	bool nms = true;
	// Most memory create() may set aside for the frame-sized buffers, bytes (0: no limit).
	// The need is estimated from the model and the frame size before anything is
	// allocated (the largest pyramid image is the frame at resize * 2^nOctUp: about 12
	// bytes per pixel of it, plus 28 per thread); beyond the budget create() returns
	// OutOfMemory with both numbers. The default, 1 GiB, takes a 1920x1080 frame with the
	// INRIA model at resize 3.5 on one thread, at resize 2 on four.
	uint64_t memoryBudgetBytes = uint64_t(1) << 30;
	// Threads detect() works on, the calling one included: 1..64. create() starts
	// threads - 1 workers once; each frame splits its colour conversion, the computed
	// levels' rectangles and the levels' preparation and classification over them, and
	// gathers the candidates in level order, so the detections are byte-identical for
	// any value. More threads than cores only adds waiting. Each thread has its own
	// scratch (the pyramid's per-level buffers and a candidate lane; pages it never
	// writes are not resident).
	// The library's default is 1; the programs and the GStreamer element take
	// recommendedThreads().
	int threads = 1;

	// A camera (copied by create()) gives detections their ground position and world
	// height, and is what the calibrated method needs. Its pixels are the input frame's
	// (before resize): every frame must then be exactly maxWidth x maxHeight.
	const CameraModel *camera = nullptr;
	DetectionMethod method = DetectionMethod::Auto;
	// The calibrated method's settings; empty means the defaults. Refused with the
	// generic method.
	std::optional<CalibratedSettings> calibrated;
	// Set: static-scene rejection, with these settings (either method; off by default).
	std::optional<StaticRejection> staticRejection;

	// InvalidArgument naming the first setting that is out of range or meaningless with
	// the others (e.g. calibrated settings with the generic method); create() calls it
	// before allocating anything.
	Status validate() const;
	// The method that runs: Auto resolved by the camera.
	DetectionMethod resolvedMethod() const;
};

// One detection in input-image pixels: top-left corner, size, classifier score. With a
// calibration, also where the person stands on the ground (metres, world x and y) and
// the box's world height (metres); NaN without one, or when the foot is above the horizon.
// The threads a detector should use on this machine: the online cores, at most 4 (a camera
// board has four; each thread reserves its own scratch, which memoryBudgetBytes counts, and
// a frame's few large sections split no further). What the programs' --threads and the
// GStreamer element's `threads` default to.
int recommendedThreads();

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
	// (with smoothing and padding, and LDCF's filter stage), classification, calibrated candidate generation and
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
	// The configuration as validated, method resolved and calibrated settings filled in
	// when the calibrated method runs.
	const DetectorConfig &config() const;

private:
	friend class DetectorInternals; // tests (lib/src/detect/detector_internals.h)
	Detector() = default;
	std::unique_ptr<DetectorImpl> impl_;
};

} // namespace calped
