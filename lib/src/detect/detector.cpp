// SPDX-License-Identifier: BSD-2-Clause
#include <calped/detector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>

#include "detect/detector_impl.h"
#include "detect/nms.h"
#include "pyramid/placement.h"

namespace calped {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

int scaledSize(int size, double resize) { return int(std::lround(size * resize)); }

} // namespace

Status DetectorImpl::init(const Model &model, const DetectorConfig &cfg)
{
	Status st = validateModel(model);
	if (!st.ok())
		return st;
	if (cfg.maxWidth < 1 || cfg.maxHeight < 1 || cfg.maxWidth > 16384 || cfg.maxHeight > 16384)
		return Status::error(ErrorCode::InvalidArgument,
				     "maximum frame size %dx%d is outside 1..16384", cfg.maxWidth,
				     cfg.maxHeight);
	if (!(cfg.resize > 0.0 && cfg.resize <= 8.0))
		return Status::error(ErrorCode::InvalidArgument, "resize %g is outside (0, 8]",
				     cfg.resize);
	if (cfg.maxCandidates < 1 || cfg.maxCandidates > (1 << 24))
		return Status::error(ErrorCode::InvalidArgument,
				     "maxCandidates %d is outside 1..16777216", cfg.maxCandidates);
	if (cfg.resizeInPyramid && cfg.resize < 1.0)
		return Status::error(ErrorCode::InvalidArgument,
				     "resize %g inside the pyramid: it only upscales (resize >= 1)",
				     cfg.resize);
	config = cfg;
	params_ = model.params;
	frameResize_ = cfg.resizeInPyramid ? 1.0 : cfg.resize;
	maxWidth_ = scaledSize(cfg.maxWidth, frameResize_);
	maxHeight_ = scaledSize(cfg.maxHeight, frameResize_);
	if (maxWidth_ < 1 || maxHeight_ < 1)
		return Status::error(ErrorCode::InvalidArgument, "resize %g leaves no pixels",
				     cfg.resize);

	st = pyramid.init(params_, maxWidth_, maxHeight_, kernels::bestKernels(),
			  cfg.resizeInPyramid ? cfg.resize : 1.0);
	if (!st.ok())
		return st;
	// Camera formats are converted a strip at a time, or whole before an input resize.
	st = input_.init(cfg.maxWidth, cfg.maxHeight, frameResize_ != 1.0);
	if (!st.ok())
		return st;
	try {
		classifier.init(model, pyramid.rowStride(), pyramid.planeStride());
		if (!std::isnan(cfg.cascadeThreshold))
			classifier.setCascadeThreshold(cfg.cascadeThreshold);
		if (frameResize_ != 1.0) {
			resized_.assign(size_t(maxWidth_) * maxHeight_ * 3, 0);
			const size_t taps = size_t(std::max(maxWidth_, maxHeight_)) + 8;
			resizeX_.resize(taps);
			resizeY_.resize(taps);
			resizeRow_.assign(size_t(cfg.maxWidth) * 3 + 8, 0);
			resizeTapsForMax_ =
				kernels::buildResampleTaps(cfg.maxWidth, maxWidth_, 1.0, resizeX_.data()) &&
				kernels::buildResampleTaps(cfg.maxHeight, maxHeight_, 1.0, resizeY_.data());
		}
		if (cfg.camera) {
			camera_ = *cfg.camera;
			hasCamera_ = true;
		}
		// The calibration's pixels must be the frames' (a Tsai file states its size).
		if (hasCamera_ && camera_.imageWidth() > 0 &&
		    (camera_.imageWidth() != cfg.maxWidth || camera_.imageHeight() != cfg.maxHeight))
			return Status::error(ErrorCode::InvalidArgument,
					     "the calibration is for %dx%d images, the detector for %dx%d",
					     camera_.imageWidth(), camera_.imageHeight(), cfg.maxWidth,
					     cfg.maxHeight);
		hits_.resize(cfg.maxCandidates);
		candidates_.resize(cfg.maxCandidates);
		sorted_.resize(cfg.maxCandidates);
		order_.resize(cfg.maxCandidates);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "detector buffers do not fit in memory");
	}
	if (cfg.staticRejection.enabled) {
		st = static_.init(cfg.maxWidth, cfg.maxHeight, cfg.staticRejection);
		if (!st.ok())
			return st;
	}
	if (cfg.calibratedPyramid && cfg.method != DetectionMethod::Calibrated)
		return Status::error(ErrorCode::InvalidArgument,
				     "calibratedPyramid places levels for the calibrated method only");
	if (cfg.calibratedPyramid && (cfg.placedLevelReach < 1 || cfg.placedLevelReach > 16))
		return Status::error(ErrorCode::InvalidArgument,
				     "placedLevelReach %d is outside 1..16 levels", cfg.placedLevelReach);
	// Placed levels are resampled from the frame: resizing it first would only add work.
	if (cfg.calibratedPyramid && frameResize_ != 1.0)
		return Status::error(ErrorCode::InvalidArgument,
				     "calibratedPyramid with resize %g needs resizeInPyramid", cfg.resize);
	if (cfg.method == DetectionMethod::Calibrated)
		return initCalibrated();
	return Status::success();
}

Status DetectorImpl::initCalibrated()
{
	if (!hasCamera_)
		return Status::error(ErrorCode::InvalidArgument,
				     "calibrated mode needs a camera (DetectorConfig::camera)");
	// The plan holds for one frame size: the configured maximum.
	ScaleList scales;
	Status st = pyramid.scalesFor(maxWidth_, maxHeight_, scales);
	if (!st.ok())
		return st;
	st = plan_.build(camera_, params_, scales, frameResize_, pyramid.padCellsH(),
			 pyramid.padCellsW(), classifier, config.minPersonHeight,
			 config.maxPersonHeight);
	if (!st.ok())
		return st;
	for (int i = 0; i < scales.count; i++) {
		levelNeeded_[i] = plan_.levelNeeded(i);
		levelRows_[i] = plan_.levelRows(i);
	}
	if (config.calibratedPyramid) {
		int source[kMaxLevels];
		if (chooseComputedLevels(params_, scales, levelRows_, pyramid.channelMargin(),
					 config.placedLevelReach, maxWidth_, maxHeight_, source)) {
			st = pyramid.placeComputedLevels(source, scales.count);
			if (!st.ok())
				return st;
		}
	}
	planLevels_ = scales.count;
	rectsPerFrameAllowed_ = config.sparseDense && pyramid.rectsComputable(maxWidth_, maxHeight_);
	rectsPerFrame_ = rectsPerFrameAllowed_;
	for (int i = 0; i < scales.count; i++) {
		sparseList_[i] = plan_.sparseWindows(i);
		sparseListCount_[i] = plan_.sparseCount(i);
	}
	gateSparse_ = config.sparseDense && config.staticRejection.enabled &&
		      config.staticRejection.gateSparse;
	if (gateSparse_) {
		size_t total = 0;
		for (int i = 0; i < scales.count; i++)
			total += plan_.sparseCount(i);
		try {
			sparseCells_.resize(total);
			movingSparse_.resize(total);
		} catch (const std::bad_alloc &) {
			return Status::error(ErrorCode::OutOfMemory, "static-scene gate of the sparse grid");
		}
		// The static scene's cells are 4x4 pixels of the (maximum-size) input frame.
		size_t k = 0;
		for (int i = 0; i < scales.count; i++)
			for (size_t j = 0; j < plan_.sparseCount(i); j++) {
				const uint32_t w = plan_.sparseWindows(i)[j];
				sparseCells_[k++] = StaticScene::cellsOf(
					boxOfWindow(scales.levels[i], int(w >> 16), int(w & 0xFFFF)),
					maxWidth_ / 4, maxHeight_ / 4);
			}
	}
	if (config.denseRegionPersistence < 1 || config.maxDenseRegions < 1)
		return Status::error(ErrorCode::InvalidArgument,
				     "dense region persistence %d and capacity %d must be >= 1",
				     config.denseRegionPersistence, config.maxDenseRegions);
	try {
		regions_.init(config.maxDenseRegions, config.denseRegionPersistence);
		evaluated_.assign(plan_.gridSize(), 0);
		frameList_.assign(plan_.largestLevelWindows() + 1, 0);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "calibrated mode buffers");
	}
	return Status::success();
}

double DetectorImpl::classifyList(int i, const LevelChannels &channels, const uint32_t *windows,
				  size_t count)
{
	const auto t0 = Clock::now();
	const uint64_t room = uint64_t(config.maxCandidates - candidateCount_);
	const uint64_t passed = classifier.scanList(channels, windows, count, hits_.data(), room);
	const uint64_t kept = std::min(passed, room);
	addBoxes(i, hits_.data(), int(kept));
	stats.windows += count;
	stats.candidates += passed;
	stats.droppedWindows += passed - kept;
	return msSince(t0);
}

size_t DetectorImpl::collectDense(int i, const DenseRegion &region, size_t n)
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
			frameList_[n++] = uint32_t(r) << 16 | uint32_t(c);
		}
	}
	return n;
}

void DetectorImpl::selectSparse()
{
	if (!gateSparse_)
		return; // the plan's lists, set at init
	// Until the background is trusted, every sparse window.
	const bool gate = static_.ready();
	size_t k = 0, kept = 0;
	for (int i = 0; i < planLevels_; i++) {
		const uint32_t *all = plan_.sparseWindows(i);
		const size_t n = plan_.sparseCount(i);
		uint32_t *list = movingSparse_.data() + kept;
		size_t count = 0;
		for (size_t j = 0; j < n; j++, k++)
			if (!gate || static_.moving(sparseCells_[k]))
				list[count++] = all[j];
		stats.staticSkipped += n - count;
		sparseList_[i] = list;
		sparseListCount_[i] = count;
		kept += count;
	}
}

Status DetectorImpl::classifyListed(int i, size_t n, double &ms)
{
	if (rectsPerFrame_) {
		// Level i prepared in the rectangles prepareRects() gave it (each window reads
		// inside one of them; they are two cells apart, so the smoothing at the edge of
		// one does not reach into another).
		LevelChannels channels;
		for (int k = 0; k < levelRectCount_[i]; k++)
			channels = pyramid.level(i, &levelRects_[i][k].rows, &levelRects_[i][k].cols);
		if (levelRectCount_[i] > 0)
			ms += classifyList(i, channels, frameList_.data(), n);
		return Status::success();
	}
	// Level i prepared only in the rows and columns these windows read (of the bands
	// build() computed).
	const RowBand rows = plan_.rowsRead(i, frameList_.data(), n);
	const RowBand cols = plan_.colsRead(i, frameList_.data(), n);
	ms += classifyList(i, pyramid.level(i, &rows, &cols), frameList_.data(), n);
	return Status::success();
}

Status DetectorImpl::prepareRects(int firstRegion, bool sparse)
{
	const auto t0 = Clock::now();
	int count = 0;
	for (int i = 0; i < planLevels_; i++) {
		int &n = levelRectCount_[i];
		n = 0;
		if (!levelNeeded_[i])
			continue;
		LevelRect *set = levelRects_[i];
		if (sparse)
			for (size_t k = 0; k < sparseListCount_[i]; k++) {
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
	return pyramid.ensureRects(input_, rectLevels_, rectList_, count);
}

Status DetectorImpl::classifySparseDense(double &ms)
{
	const ScaleList &scales = pyramid.scales();
	std::fill(evaluated_.begin(), evaluated_.end(), uint8_t(0));
	// Pass 1, every level: the sparse grid (what moves of it, with the static gate) and
	// the regions kept from earlier frames; with rectangles, their pyramid first.
	const int oldRegions = regions_.count();
	if (rectsPerFrame_) {
		const Status st = prepareRects(0, true);
		if (!st.ok())
			return st;
	}
	for (int i = 0; i < scales.count; i++) {
		if (!levelNeeded_[i])
			continue;
		const auto tList = Clock::now();
		uint8_t *done = evaluated_.data() + plan_.gridFirst(i);
		size_t n = 0;
		const uint32_t *sparse = sparseList_[i];
		for (size_t k = 0; k < sparseListCount_[i]; k++) {
			done[size_t(sparse[k] >> 16) * plan_.cols(i) + (sparse[k] & 0xFFFF)] = 1;
			frameList_[n++] = sparse[k];
		}
		const size_t sparseN = n;
		for (int r = 0; r < oldRegions; r++)
			n = collectDense(i, regions_[r], n);
		stats.sparseWindows += sparseN;
		stats.denseWindows += n - sparseN;
		stats.msCandidates += msSince(tList);
		// (The plausible windows' band is wider than the sparse grid's at its ends.)
		const Status st = classifyListed(i, n, ms);
		if (!st.ok())
			return st;
		stats.levels++;
	}
	const auto tRegions = Clock::now();
	// New regions around the detections outside the existing ones, best first.
	const int found = candidateCount_;
	for (int k = 0; k < found; k++)
		order_[k] = k;
	std::sort(order_.begin(), order_.begin() + found, [this](int a, int b) {
		if (candidates_[a].score != candidates_[b].score)
			return candidates_[a].score > candidates_[b].score;
		return a < b;
	});
	for (int k = 0; k < found; k++)
		regions_.addAround(candidates_[order_[k]]);
	stats.msCandidates += msSince(tRegions);
	// Pass 2: the new regions' windows, on the levels that have any. With rectangles,
	// what they read that pass 1 did not is computed first, for all levels at once.
	if (rectsPerFrame_ && regions_.count() > oldRegions) {
		const Status st = prepareRects(oldRegions, false);
		if (!st.ok())
			return st;
	}
	for (int i = 0; i < scales.count && regions_.count() > oldRegions; i++) {
		if (!levelNeeded_[i])
			continue;
		const auto tList = Clock::now();
		size_t n = 0;
		for (int r = oldRegions; r < regions_.count(); r++)
			n = collectDense(i, regions_[r], n);
		stats.msCandidates += msSince(tList);
		if (n == 0)
			continue;
		stats.denseWindows += n;
		const Status st = classifyListed(i, n, ms); // the new regions are small
		if (!st.ok())
			return st;
	}
	return Status::success();
}

void DetectorImpl::addWorldCoordinates(Detection *boxes, int n) const
{
	for (int i = 0; i < n; i++) {
		Detection &d = boxes[i];
		const Eigen::Vector2d foot(d.x + d.w / 2.0, d.y + double(d.h)), head(d.x + d.w / 2.0, d.y);
		Eigen::Vector2d ground;
		if (camera_.pixelToGround(foot, ground)) {
			d.groundX = float(ground.x());
			d.groundY = float(ground.y());
		}
		d.worldHeight = float(camera_.boxWorldHeight(foot, head));
	}
}

Status DetectorImpl::checkImage(const ImageView &image) const
{
	// Format, planes and strides (docs/pixel-formats.md), then sizes.
	const Status layout = checkImageLayout(image);
	if (!layout.ok())
		return layout;
	if (image.width > config.maxWidth || image.height > config.maxHeight)
		return Status::error(ErrorCode::ImageTooLarge,
				     "%s image %dx%d exceeds the configured maximum %dx%d",
				     pixelFormatName(image.format), image.width, image.height,
				     config.maxWidth, config.maxHeight);
	// World coordinates (and the calibrated plan) hold for the calibration's frame size.
	if (hasCamera_ && (image.width != config.maxWidth || image.height != config.maxHeight))
		return Status::error(ErrorCode::InvalidArgument,
				     "with a calibration the detector takes %dx%d frames, got %dx%d",
				     config.maxWidth, config.maxHeight, image.width, image.height);
	return Status::success();
}

Detection DetectorImpl::boxOfWindow(const PyramidLevel &l, int row, int col) const
{
	const ModelParams &p = params_;
	// The box is the model's central window, shifted back by the padding.
	const double shiftH = (p.modelDsPadH - double(p.modelDsH)) / 2 - p.padH;
	const double shiftW = (p.modelDsPadW - double(p.modelDsW)) / 2 - p.padW;
	const double r = frameResize_;
	Detection d;
	d.x = float((col * p.stride + shiftW) / l.scaleW / r);
	d.y = float((row * p.stride + shiftH) / l.scaleH / r);
	d.w = float(p.modelDsW / l.scale / r);
	d.h = float(p.modelDsH / l.scale / r);
	return d;
}

void DetectorImpl::addBoxes(int levelIndex, const kernels::WindowHit *hits, int count)
{
	const PyramidLevel &l = pyramid.scales().levels[levelIndex];
	for (int i = 0; i < count; i++) {
		Detection &d = candidates_[candidateCount_++];
		d = boxOfWindow(l, hits[i].row, hits[i].col);
		d.score = float(hits[i].score / double(1 << kScoreFracBits));
	}
}

Status DetectorImpl::detect(const ImageView &image, Detections &out)
{
	out = Detections();
	stats = FrameStats();
	Status st = checkImage(image);
	if (!st.ok())
		return st;
	const auto tStart = Clock::now();

	input_.begin(image);
	if (config.staticRejection.enabled)
		static_.observe(input_); // the frame's own pixels; its time counts as "other"
	const auto tResize = Clock::now();
	if (frameResize_ != 1.0) {
		// The resampler reads a whole RGB8 image: other formats are converted first.
		ptrdiff_t stride;
		const uint8_t *rgb = input_.wholeFrame(stride);
		const int width = image.width, height = image.height;
		const int w1 = scaledSize(width, frameResize_), h1 = scaledSize(height, frameResize_);
		if (w1 < 1 || h1 < 1)
			return Status::error(ErrorCode::ImageTooSmall, "resize leaves no pixels");
		// init() built the taps of maximum-size frames; other sizes build their own.
		const bool maxSize = width == config.maxWidth && height == config.maxHeight;
		if (!(maxSize && resizeTapsForMax_)) {
			resizeTapsForMax_ = false;
			if (!kernels::buildResampleTaps(width, w1, 1.0, resizeX_.data()) ||
			    !kernels::buildResampleTaps(height, h1, 1.0, resizeY_.data()))
				return Status::error(ErrorCode::InvalidArgument, "resize ratio too small");
			resizeTapsForMax_ = maxSize;
		}
		kernels::bestKernels().resampleRgb8(rgb, stride, width, height, resized_.data(), 3 * w1, w1, h1,
					  resizeX_.data(), resizeY_.data(), resizeRow_.data());
		input_.begin(ImageView::rgb8(resized_.data(), w1, h1));
	}
	stats.msResize = msSince(tResize);

	const bool calibrated = config.method == DetectionMethod::Calibrated;
	const bool sparseDense = calibrated && config.sparseDense;
	const RowBand *rows = nullptr;
	if (sparseDense)
		selectSparse();
	if (sparseDense && rectsPerFrame_)
		rows = noRows_; // nothing yet: prepareRects() asks for rectangles
	else if (calibrated)
		rows = levelRows_;
	st = pyramid.build(input_, rows);
	if (!st.ok())
		return st;

	const ScaleList &scales = pyramid.scales();
	candidateCount_ = 0;
	double msClassify = 0;
	if (sparseDense) {
		st = classifySparseDense(msClassify);
		if (!st.ok())
			return st;
	}
	for (int i = 0; i < scales.count && !sparseDense; i++) {
		if (calibrated && !levelNeeded_[i])
			continue;
		const LevelChannels level = pyramid.level(i);
		const auto t0 = Clock::now();
		const uint64_t room = uint64_t(config.maxCandidates - candidateCount_);
		uint64_t passed;
		if (calibrated) {
			passed = classifier.scanList(level, plan_.windows(i), plan_.windowCount(i),
						     hits_.data(), room);
			stats.windows += plan_.windowCount(i);
		} else {
			passed = classifier.scan(level, hits_.data(), room, &stats.windows);
		}
		const uint64_t kept = std::min(passed, room);
		addBoxes(i, hits_.data(), int(kept));
		stats.candidates += passed;
		stats.droppedWindows += passed - kept;
		msClassify += msSince(t0);
		stats.levels++;
	}

	const auto tNms = Clock::now();
	const float overlap = config.disableNms ? INFINITY : params_.nmsOverlap;
	const bool useUnion = params_.nmsOverlapDenominator == NmsOverlapDenominator::Union;
	int kept = nmsGreedy(candidates_.data(), candidateCount_, overlap, useUnion, order_.data(),
			     sorted_.data());
	if (calibrated && !config.disableNms && config.boxVoting)
		voteBoxes(candidates_.data(), kept, sorted_.data(), candidateCount_, 0.6f);
	if (calibrated && !config.disableNms)
		kept = suppressByScoreRatio(candidates_.data(), kept, order_.data());
	if (hasCamera_)
		addWorldCoordinates(candidates_.data(), kept);
	if (sparseDense) {
		const auto tUpdate = Clock::now();
		regions_.update(candidates_.data(), kept);
		stats.msCandidates += msSince(tUpdate);
		stats.denseRegions = regions_.count();
		stats.droppedRegions = regions_.dropped();
	}
	if (config.staticRejection.enabled) {
		// After the dense regions took the detections: a region around static
		// structure stays (its windows are found again anyway), only the output drops it.
		const int before = kept;
		kept = static_.reject(candidates_.data(), kept);
		stats.staticRejected = before - kept;
		static_.update();
	}
	stats.msNms = msSince(tNms);

	stats.computedLevels = pyramid.computedCount;
	stats.msChannels = pyramid.msChannels;
	stats.msApprox = pyramid.msApprox + pyramid.msSmooth;
	stats.msClassify = msClassify;
	stats.msTotal = msSince(tStart);
	out.items = candidates_.data();
	out.count = kept;
	return Status::success();
}

Status Detector::create(const Model &model, const DetectorConfig &config,
			std::unique_ptr<Detector> &out)
{
	out.reset();
	std::unique_ptr<Detector> d(new (std::nothrow) Detector());
	if (!d)
		return Status::error(ErrorCode::OutOfMemory, "detector");
	d->impl_.reset(new (std::nothrow) DetectorImpl());
	if (!d->impl_)
		return Status::error(ErrorCode::OutOfMemory, "detector");
	Status st = d->impl_->init(model, config);
	if (!st.ok())
		return st;
	out = std::move(d);
	return Status::success();
}

Detector::~Detector() = default;

Status Detector::detect(const ImageView &image, Detections &out)
{
	return impl_->detect(image, out);
}

const FrameStats &Detector::lastStats() const { return impl_->stats; }
const DetectorConfig &Detector::config() const { return impl_->config; }

} // namespace calped
