// SPDX-License-Identifier: BSD-2-Clause
#include "search/calibrated_search.h"

#include <algorithm>
#include <new>

#include "core/stage_clock.h"
#include "pyramid/placement.h"

namespace calped {

Status CalibratedSearch::init(const CameraModel &camera, const ModelParams &params,
			      const CalibratedSettings &settings, const WindowBoxes &boxes,
			      int frameW, int frameH, int maxCandidates, Pyramid &pyramid,
			      const Classifier &classifier, const StaticScene *scene, ThreadPool *pool)
{
	settings_ = settings;
	pool_ = pool;
	// The plan holds for one frame size: the configured maximum.
	ScaleList scales;
	Status st = pyramid.scalesFor(frameW, frameH, scales);
	if (!st.ok())
		return st;
	st = plan_.build(camera, params, scales, boxes, pyramid.padCellsH(), pyramid.padCellsW(),
			 classifier, settings.minPersonHeight, settings.maxPersonHeight);
	if (!st.ok())
		return st;
	levels_ = scales.count;
	size_t plausible = 0;
	for (int i = 0; i < levels_; i++)
		plausible += plan_.windowCount(i);
	// A camera that sees no ground, or no person of those heights anywhere in the frame,
	// would run without a single window: a wrong calibration, not a quiet scene.
	if (plausible == 0)
		return Status::error(ErrorCode::InvalidArgument,
				     "the calibration leaves no window where a person %g-%g m tall could "
				     "stand in %dx%d frames (does the camera see the ground?)",
				     settings.minPersonHeight, settings.maxPersonHeight, frameW, frameH);
	bandCount_ = 0;
	for (int i = 0; i < levels_; i++) {
		levelNeeded_[i] = plan_.levelNeeded(i);
		levelRows_[i] = plan_.levelRows(i);
		sparseList_[i] = plan_.sparseWindows(i);
		sparseCount_[i] = plan_.sparseCount(i);
		if (!levelRows_[i].empty()) {
			bandLevels_[bandCount_] = i;
			bandRects_[bandCount_++] = LevelRect{ levelRows_[i], CellRange{ 0, 1 << 30 } };
		}
	}
	if (settings.levels == PyramidLevels::Placed) {
		int source[kMaxLevels];
		if (choosePlacedLevels(params, scales, levelRows_, pyramid.channelMargin(),
					 settings.placedLevelReach, frameW, frameH, source)) {
			st = pyramid.placeLevels(source, scales.count);
			if (!st.ok())
				return st;
		}
	}
	rectsAllowed_ = settings.sparseDense && pyramid.rectsComputable(frameW, frameH);
	rectsPerFrame_ = rectsAllowed_;
	scene_ = settings.sparseDense ? scene : nullptr;
	gate_ = scene_ != nullptr;
	try {
		if (scene_) {
			size_t total = 0;
			for (int i = 0; i < levels_; i++)
				total += plan_.sparseCount(i);
			sparseCells_.resize(total);
			movingSparse_.resize(total);
			// The static scene's cells are 4x4 pixels of the (maximum-size) frame.
			size_t k = 0;
			for (int i = 0; i < levels_; i++)
				for (size_t j = 0; j < plan_.sparseCount(i); j++) {
					const uint32_t w = plan_.sparseWindows(i)[j];
					const WindowBox b = boxes.box(scales.levels[i], int(w >> 16), int(w & 0xFFFF));
					Detection d;
					d.x = float(b.x);
					d.y = float(b.y);
					d.w = float(b.w);
					d.h = float(b.h);
					sparseCells_[k++] = StaticScene::cellsOf(d, frameW / 4, frameH / 4);
				}
		}
		regions_.init(settings.maxDenseRegions, settings.denseRegionPersistence);
		evaluated_.assign(plan_.gridSize(), 0);
		frameLists_.assign(size_t(pool ? pool->size() : 1),
				   std::vector<uint32_t>(plan_.largestLevelWindows() + 1, 0));
		order_.assign(size_t(maxCandidates), 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "calibrated search buffers");
	}
	return Status::success();
}

void CalibratedSearch::beginFrame(FrameStats &stats)
{
	if (!settings_.sparseDense || !gate_)
		return; // the plan's lists, set up once
	// Until the background is trusted, every sparse window.
	const bool ready = scene_->ready();
	size_t k = 0, kept = 0;
	for (int i = 0; i < levels_; i++) {
		const uint32_t *all = plan_.sparseWindows(i);
		const size_t n = plan_.sparseCount(i);
		uint32_t *list = movingSparse_.data() + kept;
		size_t count = 0;
		for (size_t j = 0; j < n; j++, k++)
			if (!ready || scene_->moving(sparseCells_[k]))
				list[count++] = all[j];
		stats.staticSkipped += n - count;
		sparseList_[i] = list;
		sparseCount_[i] = count;
		kept += count;
	}
}

Status CalibratedSearch::run(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
			     Candidates &out, FrameStats &stats)
{
	if (!rectsPerFrame_) {
		const Status st = pyramid.compute(input, PyramidDemand::of(bandLevels_, bandRects_, bandCount_));
		if (!st.ok())
			return st;
	}
	if (!settings_.sparseDense) {
		// Every plausible window, in the plan's bands, level after level on the threads.
		int count = 0;
		for (int i = 0; i < levels_; i++)
			if (levelNeeded_[i])
				passLevels_[count++] = i;
		long cost[kMaxLevels];
		for (int t = 0; t < count; t++)
			cost[t] = long(plan_.windowCount(passLevels_[t]));
		orderPassLevels(count, cost);
		out.emptyLanes();
		auto one = [&](int task, int worker) {
			const int t = passOrder_[task];
			const int i = passLevels_[t];
			LevelWork &work = work_[t];
			const LevelChannels level = pyramid.classifierLevel(i, nullptr, 0, worker);
			const auto t0 = StageClock::now();
			work.hits = out.classifyInLane(worker, classifier, pyramid.scales().levels[i], level,
						       plan_.windows(i), plan_.windowCount(i));
			work.msClassify = msSince(t0);
		};
		forEachTask(pool_, count, one);
		for (int t = 0; t < count; t++) {
			out.gather(&work_[t].hits, 1, stats);
			stats.msClassify += work_[t].msClassify;
			stats.levels++;
		}
		return Status::success();
	}
	std::fill(evaluated_.begin(), evaluated_.end(), uint8_t(0));
	// Pass 1, every level: the sparse grid and the regions kept from earlier frames.
	const int oldRegions = regions_.count();
	Status st = pass(input, pyramid, classifier, out, stats, 0, true);
	if (!st.ok())
		return st;
	// New regions around the candidates outside the existing ones, best first.
	const auto tRegions = StageClock::now();
	const int found = out.count();
	const Detection *c = out.data();
	for (int k = 0; k < found; k++)
		order_[size_t(k)] = k;
	std::sort(order_.begin(), order_.begin() + found, [c](int a, int b) {
		if (c[a].score != c[b].score)
			return c[a].score > c[b].score;
		return a < b;
	});
	for (int k = 0; k < found; k++)
		regions_.addAround(c[order_[size_t(k)]]);
	stats.msCandidates += msSince(tRegions);
	// Pass 2: the new regions' windows, on the levels that have any.
	if (regions_.count() > oldRegions)
		st = pass(input, pyramid, classifier, out, stats, oldRegions, false);
	return st;
}

Status CalibratedSearch::pass(FrameInput &input, Pyramid &pyramid, const Classifier &classifier,
			      Candidates &out, FrameStats &stats, int firstRegion, bool sparse)
{
	// With rectangles, the pyramid first: for pass 2, what the new regions read that
	// pass 1 did not.
	if (rectsPerFrame_) {
		const Status st = prepareRects(input, pyramid, stats, firstRegion, sparse);
		if (!st.ok())
			return st;
	}
	// Each needed level on some thread: its window list, preparation and classification
	// write only its own outputs; the hits are gathered in level order.
	int count = 0;
	for (int i = 0; i < levels_; i++)
		if (levelNeeded_[i])
			passLevels_[count++] = i;
	// The cost of a level: the cells it prepares (with rectangles) or the windows it
	// may classify.
	long cost[kMaxLevels];
	for (int t = 0; t < count; t++) {
		const int i = passLevels_[t];
		cost[t] = long(sparseCount_[i]);
		if (rectsPerFrame_) {
			cost[t] = 0;
			for (int k = 0; k < levelRectCount_[i]; k++)
				cost[t] += long(levelRects_[i][k].rows.size()) * levelRects_[i][k].cols.size();
		}
	}
	orderPassLevels(count, cost);
	out.emptyLanes();
	auto one = [&](int task, int worker) {
		const int t = passOrder_[task];
		work_[t] = LevelWork();
		passLevel(passLevels_[t], worker, pyramid, classifier, out, firstRegion, sparse, work_[t]);
	};
	forEachTask(pool_, count, one);
	for (int t = 0; t < count; t++) {
		const LevelWork &work = work_[t];
		stats.sparseWindows += work.sparse;
		stats.denseWindows += work.dense;
		stats.msCandidates += work.msList;
		stats.msClassify += work.msClassify;
		if (work.classified)
			out.gather(&work.hits, 1, stats);
		if (sparse)
			stats.levels++;
	}
	return Status::success();
}

void CalibratedSearch::orderPassLevels(int count, const long *cost)
{
	for (int t = 0; t < count; t++)
		passOrder_[t] = t;
	std::sort(passOrder_, passOrder_ + count, [cost](int a, int b) {
		return cost[a] != cost[b] ? cost[a] > cost[b] : a < b;
	});
}

void CalibratedSearch::passLevel(int i, int worker, Pyramid &pyramid, const Classifier &classifier,
				 Candidates &out, int firstRegion, bool sparse, LevelWork &work)
{
	const auto tList = StageClock::now();
	uint32_t *list = frameLists_[size_t(worker)].data();
	size_t n = 0;
	if (sparse) {
		uint8_t *done = evaluated_.data() + plan_.gridFirst(i);
		const uint32_t *sparseList = sparseList_[i];
		for (size_t k = 0; k < sparseCount_[i]; k++) {
			done[size_t(sparseList[k] >> 16) * plan_.cols(i) + (sparseList[k] & 0xFFFF)] = 1;
			list[n++] = sparseList[k];
		}
		work.sparse = n;
	}
	const size_t sparseN = n;
	for (int r = firstRegion; r < regions_.count(); r++)
		n = collectDense(i, regions_[r], list, n);
	work.dense = n - sparseN;
	work.msList = msSince(tList);
	// Pass 1 classifies every needed level (the plausible windows' band is wider than
	// the sparse grid's at its ends); pass 2 only those with new windows.
	if (!sparse && n == 0)
		return;
	classifyListed(i, list, n, worker, pyramid, classifier, out, work);
}

void CalibratedSearch::classifyListed(int i, const uint32_t *list, size_t n, int worker,
				      Pyramid &pyramid, const Classifier &classifier,
				      Candidates &out, LevelWork &work)
{
	const PyramidLevel &level = pyramid.scales().levels[i];
	LevelChannels channels;
	if (rectsPerFrame_) {
		// Level i prepared in each of the rectangles prepareRects() gave it (each window
		// reads inside one of them; they are two cells apart, so the smoothing at the
		// edge of one does not reach into another).
		if (levelRectCount_[i] == 0)
			return;
		channels = pyramid.classifierLevel(i, levelRects_[i], levelRectCount_[i], worker);
	} else {
		// Level i prepared only in the rows and columns these windows read (of the
		// plan's bands).
		const LevelRect read{ plan_.rowsRead(i, list, n), plan_.colsRead(i, list, n) };
		channels = pyramid.classifierLevel(i, &read, 1, worker);
	}
	const auto t0 = StageClock::now();
	work.hits = out.classifyInLane(worker, classifier, level, channels, list, n);
	work.classified = true;
	work.msClassify = msSince(t0);
}

size_t CalibratedSearch::collectDense(int i, const DenseRegion &region, uint32_t *list, size_t n)
{
	int r0, r1, c0, c1;
	if (!plan_.windowsInside(i, region.x0, region.y0, region.x1, region.y1, r0, r1, c0, c1))
		return n;
	uint8_t *done = evaluated_.data() + plan_.gridFirst(i);
	const int cols = plan_.cols(i);
	for (int c = c0; c <= c1; c++) {
		// Only the rows where this column has plausible windows.
		int first, last;
		plan_.plausibleRows(i, c, first, last);
		for (int r = std::max(r0, first); r <= std::min(r1, last); r++) {
			const size_t k = size_t(r) * cols + c;
			if (done[k] || !plan_.plausible(i, r, c))
				continue;
			done[k] = 1;
			list[n++] = uint32_t(r) << 16 | uint32_t(c);
		}
	}
	return n;
}

Status CalibratedSearch::prepareRects(FrameInput &input, Pyramid &pyramid, FrameStats &stats,
				      int firstRegion, bool sparse)
{
	const auto t0 = StageClock::now();
	int count = 0;
	for (int i = 0; i < levels_; i++) {
		int &n = levelRectCount_[i];
		n = 0;
		if (!levelNeeded_[i])
			continue;
		LevelRect *set = levelRects_[i];
		if (sparse)
			for (size_t k = 0; k < sparseCount_[i]; k++) {
				const int r = int(sparseList_[i][k] >> 16), c = int(sparseList_[i][k] & 0xFFFF);
				addMerged(set, n, Pyramid::kMaxRects, plan_.windowsRect(i, r, r, c, c), 2);
			}
		for (int g = firstRegion; g < regions_.count(); g++) {
			const DenseRegion &region = regions_[g];
			int r0, r1, c0, c1;
			if (!plan_.windowsInside(i, region.x0, region.y0, region.x1, region.y1, r0, r1, c0, c1))
				continue;
			// Only the rows where the region's columns have plausible windows.
			int first = r1 + 1, last = r0 - 1;
			for (int c = c0; c <= c1; c++) {
				int f, l;
				plan_.plausibleRows(i, c, f, l);
				if (std::max(f, r0) <= std::min(l, r1)) {
					first = std::min(first, std::max(f, r0));
					last = std::max(last, std::min(l, r1));
				}
			}
			if (first <= last)
				addMerged(set, n, Pyramid::kMaxRects, plan_.windowsRect(i, first, last, c0, c1), 2);
		}
		for (int k = 0; k < n; k++) {
			rectLevels_[count] = i;
			rectList_[count++] = set[k];
		}
	}
	stats.msCandidates += msSince(t0);
	return pyramid.compute(input, PyramidDemand::of(rectLevels_, rectList_, count));
}

void CalibratedSearch::setStaticGate(bool on)
{
	gate_ = on && scene_ != nullptr;
	// Ungated, every frame has the plan's sparse lists.
	for (int i = 0; i < levels_; i++) {
		sparseList_[i] = plan_.sparseWindows(i);
		sparseCount_[i] = plan_.sparseCount(i);
	}
}

void CalibratedSearch::endFrame(const Detection *detections, int count, FrameStats &stats)
{
	if (!settings_.sparseDense)
		return;
	const auto t0 = StageClock::now();
	regions_.update(detections, count);
	stats.msCandidates += msSince(t0);
	stats.denseRegions = regions_.count();
	stats.droppedRegions = regions_.dropped();
}

} // namespace calped
