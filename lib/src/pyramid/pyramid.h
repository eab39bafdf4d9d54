// SPDX-License-Identifier: BSD-2-Clause
// The fast feature pyramid (the toolbox's chnsPyramid): channels computed at one scale
// per octave, the scales between them approximated by resampling the nearest computed
// level and correcting with the power law; every level then smoothed and padded, ready
// for the sliding-window classifier. All buffers are sized once, in init().
#pragma once

#include <calped/model.h>
#include <calped/status.h>

#include <memory>
#include <vector>

#include "channels/channel_computer.h"
#include "input/frame_input.h"
#include "core/plane.h"
#include "core/thread_pool.h"
#include "kernels.h"
#include "pyramid/cell_range.h"
#include "pyramid/ldcf_filter.h"
#include "pyramid/level_channels.h"
#include "pyramid/scales.h"

namespace calped {

// What a pass of the search will read: rectangles of levels (cells before padding), or
// every level whole. Points into the caller's arrays.
struct PyramidDemand {
	bool everything = false;
	const int *levels = nullptr;       // level of each rectangle
	const LevelRect *rects = nullptr;
	int count = 0;

	static PyramidDemand wholeFrame()
	{
		PyramidDemand d;
		d.everything = true;
		return d;
	}
	static PyramidDemand of(const int *levels, const LevelRect *rects, int count)
	{
		PyramidDemand d;
		d.levels = levels;
		d.rects = rects;
		d.count = count;
		return d;
	}
};

class Pyramid
{
public:
	// maxWidth x maxHeight: the largest RGB image compute() will see (after any resize).
	// upscale >= 1: the levels are those of the image resized by this factor, each
	// resampled from the image's colour channels (computeScales) instead of the image
	// being resized first. pool (optional, outliving the pyramid): compute() splits its
	// colour rows and rectangles over it, and prepare() may run on each of its threads
	// at once for different levels (one scratch set per thread).
	Status init(const ModelParams &params, int maxWidth, int maxHeight,
		    const kernels::KernelTable &k = kernels::bestKernels(), double upscale = 1.0,
		    ThreadPool *pool = nullptr);
	// Threads that may prepare() levels at once (the pool's size, or 1).
	int workers() const { return int(scratch_.size()); }

	// The one way channels get computed. A frame starts with beginFrame(); each compute()
	// then computes what `demand` needs that the frame has not computed yet: colour
	// conversion, the computed levels' channels (with their margin) and, through
	// prepare(), the approximated levels. The whole frame is one demand. Rectangles are
	// computed as such when every computed level comes from the image itself (placed
	// levels, or octaves without a half-size source); otherwise a frame takes one demand
	// (full-width bands of the rows it asks for) and later ones must lie inside it.
	void beginFrame() { frameDemands_ = 0; }
	Status compute(FrameInput &input, const PyramidDemand &demand);
	// The same for an RGB8 image in memory.
	Status compute(const uint8_t *rgb, ptrdiff_t stride, int width, int height,
		       const PyramidDemand &demand = PyramidDemand::wholeFrame())
	{
		FrameInput input;
		input.begin(ImageView::rgb8(rgb, width, height, int(stride)));
		beginFrame();
		return compute(input, demand);
	}
	static constexpr int kMaxRects = 32; // rectangles kept per level and frame
	// Whether compute() works in rectangles for images of this size.
	bool rectsComputable(int width, int height) const;

	// The scale list compute() will use for an image of this size (for setup).
	Status scalesFor(int width, int height, ScaleList &out) const;

	// Compute the channels of other levels than the toolbox's octaves (placement.h):
	// source[i] is the computed level that level i is approximated from (i itself when
	// computed), for the scale list of maxWidth x maxHeight images; other sizes keep
	// the toolbox's. Setup time: may grow the channel store.
	Status placeLevels(const int *source, int count);
	// LUV rows a computed level's channels need beyond its channel rows (each side).
	int channelMargin() const { return channelMargin_; }

	const ScaleList &scales() const { return scales_; }

	// Level i smoothed and padded for the classifier (approximated first if need be):
	// all that compute() prepared of it (rects null), or only these rectangles (cells
	// before padding, each inside what was demanded); everything outside is stale.
	// worker (0 .. workers()-1): whose scratch holds the result; calls with different
	// workers may run at once (between compute() calls), for different levels.
	LevelChannels prepare(int i, const LevelRect *rects = nullptr, int count = 0, int worker = 0);

	ptrdiff_t rowStride() const { return rowStride_; }
	ptrdiff_t planeStride() const { return planeStride_; }

	// LDCF (a model with filters): the filter stage after prepare(), one per thread
	// (pyramid/ldcf_filter.h), sized for this pyramid's largest level. Setup time.
	Status setFilters(const Model &model);
	bool filtered() const { return filtered_; }
	// Level i as the classifier reads it: prepare(i, rects, count, worker), and with
	// filters the filter stage: on demand for rectangles (LdcfFilter::onDemand, exact where
	// the filter reads only inside them: the calibrated method grows its rectangles by
	// LdcfFilter::levelCellsRead), at once for the whole level (LdcfFilter::apply).
	LevelChannels classifierLevel(int i, const LevelRect *rects = nullptr, int count = 0,
				      int worker = 0);
	// The strides of classifierLevel()'s planes.
	ptrdiff_t classifierRowStride() const;
	ptrdiff_t classifierPlaneStride() const;
	int padCellsH() const { return padH_; }
	int padCellsW() const { return padW_; }

	// Levels whose channels this frame computed.
	int computedCount = 0;
	// Rectangles computed as such since init (tests, tuning).
	long rectsComputed = 0;
	// Time spent on this frame in compute(), and in prepare() summed over the threads.
	double msChannels = 0;
	double msApprox() const;
	double msSmooth() const;
	double msFilter() const; // LDCF's filter stage

private:
	// What one thread writes while computing a rectangle or preparing a level.
	struct Scratch {
		ChannelComputer channels;
		PlaneBuffer<uint16_t> levelLuv[3]; // image resampled to one computed scale
		PlaneBuffer<uint16_t> resampleTmp;
		PlaneBuffer<uint16_t> approx;      // channels of one approximated level (or rectangle)
		PlaneBuffer<uint16_t> levelBuf;    // smoothed and padded level for the classifier
		PlaneBuffer<uint8_t> strip;        // RGB rows of a non-RGB8 frame
		// Taps built per frame for frames smaller than the maximum, one buffer per kind
		// (kTapsX, kTapsY + channel type: each type has its own gain).
		std::vector<kernels::ResampleTap> taps[4];
		std::vector<kernels::ResampleTap> yTapsBand;
		std::vector<uint32_t> rowTmp;
		LdcfFilter filter; // with setFilters() only
		double msApprox = 0, msSmooth = 0, msFilter = 0;
	};
	Status allocateScratch(Scratch &s, int luvW, int luvH, int maxWidth);

	// Full-width bands of every level (levelRows: one per level, rows before padding;
	// null: whole levels): the frame's colour and computed levels there, from scratch.
	Status computeBands(FrameInput &input, const CellRange *levelRows);
	// After computeBands(), the rectangles of a demand not computed yet this frame.
	Status computeRects(FrameInput &input, const int *levels, const LevelRect *rects, int count);
	// Level i smoothed and padded in rows `only` and columns `onlyCols` of what was
	// computed (null: all of it).
	LevelChannels prepareRect(int i, const CellRange *only, const CellRange *onlyCols, Scratch &s);

	// The rows each stage must produce for the bands the classifier needs.
	struct LevelRows {
		CellRange raw;    // raw channel rows (those the classifier reads plus the smoothing's reach)
		CellRange chan;   // computed levels: rows of the level's LUV image fed to the channels
		CellRange luv;    // computed levels: rows of its LUV image that must exist (chan, and
				// for the half-size image the rows smaller octaves resample)
	};
	void planRows(const CellRange *levelRows, int width, int height);
	// dst[p]'s `rows` from src[p], in all of their columns or only in `cols`, for planes
	// of one size sharing xTaps; yTaps[p] holds at most kMaxTapSets distinct pointers.
	// dst's row 0 is the level's row dstFirstRow (a buffer holding only some rows).
	void resampleRows(const Plane<uint16_t> *src, const Plane<uint16_t> *dst, int planes,
			  const kernels::ResampleTap *const *yTaps, const CellRange &rows,
			  const kernels::ResampleTap *xTaps, Scratch &s, const CellRange *cols = nullptr,
			  int dstFirstRow = 0);
	static constexpr int kMaxTapSets = 3; // the channel types' gains

	// Resampling taps of level i: across (kTapsX) and down (kTapsY, the first channel
	// type's gain for approximated levels; kTapsY + t for channel type t), from the
	// image or half image (computed levels) or the computed source level (approximated).
	enum { kTapsX = 0, kTapsY = 1, kTapKinds = 4 };
	static_assert(kTapKinds == sizeof(Scratch::taps) / sizeof(Scratch::taps[0]), "one buffer per kind");
	bool tapSpec(const ScaleList &scales, int width, int height, int i, int kind, int &n, int &m,
		     double &gain) const;
	// Builds every level's taps for maximum-size frames (setup time); false if some
	// computed level cannot be resampled in one step.
	bool buildTapCache();
	// Taps for the current frame: cached for maximum-size frames, else built now into
	// the scratch's buffer (valid until its next call of the same kind). nullptr: the
	// ratio is beyond the resampler.
	const kernels::ResampleTap *levelTaps(int i, int kind, Scratch &s);
	// Channels of computed level i in rectangle r (cells), exactly, from `input`; the
	// colour rows it reads must be converted already (colourRows()).
	Status computeRect(FrameInput &input, int i, const LevelRect &r, Scratch &s);
	// The whole image's colour rows that computeRect(i, r) reads.
	CellRange colourRows(int i, const LevelRect &r);
	// The colour rows `chan` of computed level i's image, in columns `chanCols`, as planes
	// whose row 0 is row chan.begin: the whole image's (converted if need be), the
	// half-size image's (resampled already by computeBands), or resampled into the first
	// rows of s.levelLuv from the whole image or, for the octaves below the half-size
	// image, from it.
	Status levelColour(FrameInput &input, int i, const CellRange &chan, const CellRange &chanCols,
			   Plane<uint16_t> in[3], Scratch &s);
	// The half-size image's rows that its level and the octaves below it read, resampled
	// from the whole image `luv` (split over the pool).
	Status resampleHalf(const Plane<uint16_t> luv[3]);
	// The whole image's LUV rows not converted yet this frame (split over the pool).
	void convertLuvRows(FrameInput &input, CellRange rows);
	void approximate(int i, const CellRange &rows, const CellRange &cols,
			 Plane<uint16_t> out[kChannelCount], Scratch &s);
	void realLevelPlanes(int i, Plane<uint16_t> out[kChannelCount]);

	ModelParams params_;
	double upscale_ = 1.0;
	const kernels::KernelTable *k_ = nullptr;
	kernels::LuvTables luvTables_;
	ThreadPool *pool_ = nullptr;
	std::vector<std::unique_ptr<Scratch>> scratch_; // one per thread of the pool
	ScaleList scales_;
	LevelRows rows_[kMaxLevels];
	// computeRects(): this frame's computed rectangles of each computed level (exact, so
	// never merged; the oldest is forgotten when full), and the rectangles asked for.
	LevelRect doneRects_[kMaxLevels][kMaxRects];
	int doneCount_[kMaxLevels] = {};
	int doneNext_[kMaxLevels] = {};
	LevelRect needRects_[kMaxLevels][kMaxRects];
	int needCount_[kMaxLevels] = {};
	// computeRects(): the rectangles still to compute (level, index into needRects_, its
	// rows, its cells), then the same cut into parts: segment s of the frame's work is
	// parts_[segmentBegin_[s] .. segmentBegin_[s + 1]), and each part's outcome.
	struct RectTask {
		int level, index;
		CellRange rows;
		long cells;
	};
	static constexpr int kMaxSegments = 64; // per frame demand; each adds at most one cut
	RectTask tasks_[kMaxLevels * kMaxRects];
	RectTask parts_[kMaxLevels * kMaxRects + kMaxSegments];
	int segmentBegin_[kMaxLevels * kMaxRects + kMaxSegments + 1];
	bool partFailed_[kMaxLevels * kMaxRects + kMaxSegments];
	// With more than one worker, cuts the rectangles' rows into about 2 x workers
	// segments of equal cells (one may end one rectangle and start the next), so that
	// the threads finish together: one rectangle can be most of a frame's work. With one,
	// each rectangle is its own segment. Returns the number of segments.
	int cutIntoSegments(int tasks);
	// tasks_[0 .. tasks) cut into segments and computed over the pool (computeRect);
	// `parts`: how many parts of parts_ they became.
	Status computeTasks(FrameInput &input, int tasks, int &parts);
	CellRange fullRows_; // rows of the whole-image LUV planes the levels read
	int halfLevel_ = -1; // the computed level at scale 1/2, source of smaller octaves
	int frameDemands_ = 0; // compute() calls since beginFrame()
	CellRange demandBands_[kMaxLevels]; // a band frame's demand, as rows per level
	int channelMargin_ = 8;
	int width_ = 0, height_ = 0;
	int maxWidth_ = 0, maxHeight_ = 0;
	// placeLevels(): sources for the maximum frame size's levels, if set.
	int placedCount_ = 0;
	int placedSource_[kMaxLevels] = {};
	int padH_ = 0, padW_ = 0;
	bool filtered_ = false;

	PlaneBuffer<uint16_t> luv_[3];      // whole image in LUV
	PlaneBuffer<uint16_t> halfLuv_[3];  // the image at scale 1/2 (source of smaller octaves)
	std::vector<kernels::ResampleTap> tapStore_; // buildTapCache()
	static constexpr size_t kNoTaps = ~size_t(0);
	size_t tapOffset_[kMaxLevels][kTapKinds];
	bool tapsCached_ = false;

	// Raw (unsmoothed, unpadded) channels of every computed level, back to back.
	PlaneBuffer<uint16_t> computedStore_; // zero pages until a level's cells are written
	size_t realOffset_[kMaxLevels] = {};
	ptrdiff_t rowStride_ = 0, planeStride_ = 0;
	int maxLevelH_ = 0, maxLevelW_ = 0;
};

} // namespace calped
