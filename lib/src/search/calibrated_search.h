// SPDX-License-Identifier: BSD-2-Clause
// The calibrated method's search (thesis 3.2): which windows of which levels are
// classified in a frame, and which parts of the pyramid that needs. With sparse and dense
// windows, two passes: pass 1 the sparse grid (with static rejection, only what moves of
// it) and the dense regions kept from earlier frames; pass 2 the regions new around pass
// 1's candidates. Without, one pass over every plausible window. Everything is sized in
// init(); a frame allocates nothing.
#pragma once

#include <calped/calibration.h>
#include <calped/detector.h>

#include <vector>

#include "classify/candidates.h"
#include "classify/classifier.h"
#include "pyramid/pyramid.h"
#include "search/calibrated_plan.h"
#include "search/dense_regions.h"
#include "search/window_boxes.h"
#include "suppress/static_scene.h"

namespace calped {

class CalibratedSearch
{
public:
	// Plans the windows of maximum-size frames (frameW x frameH after any frame resize),
	// places the pyramid's computed levels if asked, and sizes every buffer. `scene` is
	// the static scene when static rejection is on (the sparse grid is then gated by it),
	// else null.
	Status init(const CameraModel &camera, const ModelParams &params,
		    const CalibratedSettings &settings, const WindowBoxes &boxes, int frameW,
		    int frameH, int maxCandidates, Pyramid &pyramid, const Classifier &classifier,
		    const StaticScene *scene, ThreadPool *pool = nullptr);

	// Picks this frame's sparse windows (the static gate).
	void beginFrame(FrameStats &stats);
	// Classifies this frame's windows into `out`, each pass demanding from the pyramid
	// what its windows read.
	Status run(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
		   Candidates &out, FrameStats &stats);
	// Thesis 3.4, after suppression: regions without a detection age and go.
	void endFrame(const Detection *detections, int count, FrameStats &stats);

	// Test hooks (detector_internals.h): demand the plan's whole bands once per frame
	// instead of each pass's rectangles, and the gate of the sparse grid on or off.
	bool rectsPerFrame() const { return rectsPerFrame_; }
	void setRectsPerFrame(bool on) { rectsPerFrame_ = on && rectsAllowed_; }
	void setStaticGate(bool on);

private:
	// One pass of the sparse-dense search over the regions from firstRegion on (and
	// with `sparse`, this frame's sparse grid).
	Status pass(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
		    Candidates &out, FrameStats &stats, int firstRegion, bool sparse);
	// Rectangle mode: the cells each level's windows read in this pass, merged; then the
	// pyramid computes what they need.
	Status prepareRects(FrameInput &input, Pyramid &pyramid, FrameStats &stats,
			    int firstRegion, bool sparse);
	// Windows of level i inside region r not evaluated yet, appended to list.
	size_t collectDense(int i, const DenseRegion &r, uint32_t *list, size_t n);
	// What one level of a pass did, on whichever thread: its windows, its hits (in the
	// thread's lane of the candidates) and its time.
	struct LevelWork {
		bool classified = false;
		LevelHits hits;
		uint64_t sparse = 0, dense = 0;
		double msList = 0, msClassify = 0;
	};
	// Level i of a pass (its window list in the worker's own list), classified.
	void passLevel(int i, int worker, Pyramid &pyramid, const Classifier &classifier,
		       Candidates &out, int firstRegion, bool sparse, LevelWork &work);
	// Level i prepared where the first n windows of `list` read, and classified.
	void classifyListed(int i, const uint32_t *list, size_t n, int worker, Pyramid &pyramid,
			    const Classifier &classifier, Candidates &out, LevelWork &work);

	CalibratedSettings settings_;
	CalibratedPlan plan_;
	int levels_ = 0;
	bool levelNeeded_[kMaxLevels] = {};
	CellRange levelRows_[kMaxLevels]; // the rows of each level its plausible windows read
	// Without rectangles, one demand per frame: those rows of the needed levels.
	int bandLevels_[kMaxLevels] = {};
	LevelRect bandRects_[kMaxLevels];
	int bandCount_ = 0;
	// Sparse-dense with computed levels that all come from the image itself (placed
	// levels): each pass demands the rectangles around what its windows read.
	bool rectsPerFrame_ = false, rectsAllowed_ = false;
	LevelRect levelRects_[kMaxLevels][Pyramid::kMaxRects];
	int levelRectCount_[kMaxLevels] = {};
	int rectLevels_[kMaxLevels * Pyramid::kMaxRects] = {};
	LevelRect rectList_[kMaxLevels * Pyramid::kMaxRects];
	// The static gate of the sparse grid: each sparse window's box as cells of the static
	// scene (plan order, level after level), and this frame's sparse windows per level.
	const StaticScene *scene_ = nullptr;
	bool gate_ = false;
	std::vector<StaticScene::CellRect> sparseCells_;
	std::vector<uint32_t> movingSparse_;
	const uint32_t *sparseList_[kMaxLevels] = {};
	size_t sparseCount_[kMaxLevels] = {};
	DenseRegions regions_;
	std::vector<uint8_t> evaluated_; // per plan window grid: evaluated this frame
	ThreadPool *pool_ = nullptr;
	std::vector<std::vector<uint32_t>> frameLists_; // a window list per thread
	// A pass's levels in level order (its results are gathered in that order), and the
	// order the threads take them in: costliest first, so that they finish together.
	int passLevels_[kMaxLevels] = {};
	int passOrder_[kMaxLevels] = {};
	LevelWork work_[kMaxLevels];
	void orderPassLevels(int count, const long *cost);
	std::vector<int> order_; // candidates best first, for new regions
};

} // namespace calped
