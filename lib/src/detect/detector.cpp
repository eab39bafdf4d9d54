// SPDX-License-Identifier: BSD-2-Clause
#include <calped/detector.h>

#include <cmath>
#include <new>

#include "core/stage_clock.h"
#include "detect/detector_impl.h"
#include "detect/memory_estimate.h"
#include "detect/world_coordinates.h"
#include "search/generic_search.h"

namespace calped {

Status DetectorImpl::init(const Model &model, const DetectorConfig &cfg)
{
	Status st = validateModel(model);
	if (!st.ok())
		return st;
	st = cfg.validate();
	if (!st.ok())
		return st;
	const uint64_t need = estimateDetectorBytes(model.params, cfg);
	if (cfg.memoryBudgetBytes != 0 && need > cfg.memoryBudgetBytes)
		return Status::error(ErrorCode::OutOfMemory,
				     "%dx%d frames at resize %g with the model's nOctUp %d need about %.2f GiB, "
				     "over the memory budget of %.2f GiB (DetectorConfig::memoryBudgetBytes)",
				     cfg.maxWidth, cfg.maxHeight, cfg.resize, int(model.params.nOctUp),
				     double(need) / double(1 << 30), double(cfg.memoryBudgetBytes) / double(1 << 30));
	config = cfg;
	config.method = cfg.resolvedMethod();
	calibrated_ = config.method == DetectionMethod::Calibrated;
	if (calibrated_ && !config.calibrated)
		config.calibrated = CalibratedSettings();
	const ModelParams &params = model.params;
	const bool inPyramid = cfg.resizeAt == ResizeAt::Pyramid;
	const double frameResize = inPyramid ? 1.0 : cfg.resize;
	const int frameW = resizedSize(cfg.maxWidth, frameResize);
	const int frameH = resizedSize(cfg.maxHeight, frameResize);
	const WindowBoxes boxes(params, frameResize);

	st = pool_.start(cfg.threads);
	if (!st.ok())
		return st;
	ThreadPool *pool = cfg.threads > 1 ? &pool_ : nullptr;
	st = input_.init(cfg.maxWidth, cfg.maxHeight, frameResize);
	if (!st.ok())
		return st;
	st = pyramid.init(params, frameW, frameH, kernels::bestKernels(), inPyramid ? cfg.resize : 1.0, pool);
	if (!st.ok())
		return st;
	// LDCF: the trees read each level after the filter stage.
	if (params.nFilters > 0) {
		st = pyramid.setFilters(model);
		if (!st.ok())
			return st;
	}
	try {
		classifier.init(model, pyramid.classifierRowStride(), pyramid.classifierPlaneStride());
		if (cfg.camera) {
			camera_ = *cfg.camera;
			hasCamera_ = true;
			config.camera = &camera_; // the copy, not the caller's
		}
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "classifier trees do not fit in memory");
	}
	if (!std::isnan(cfg.cascadeThreshold))
		classifier.setCascadeThreshold(cfg.cascadeThreshold);
	st = candidates_.init(cfg.maxCandidates, boxes, pool_.size());
	if (!st.ok())
		return st;
	const CalibratedSettings *cal = calibrated_ ? &*config.calibrated : nullptr;
	st = suppression_.init(params, cfg.nms, cal && cal->boxVoting, cal && cal->scoreRatio,
			       cfg.maxCandidates);
	if (!st.ok())
		return st;
	rejectStatic_ = cfg.staticRejection.has_value();
	if (rejectStatic_) {
		st = static_.init(cfg.maxWidth, cfg.maxHeight, *cfg.staticRejection);
		if (!st.ok())
			return st;
	}
	if (calibrated_)
		return calibratedSearch.init(camera_, params, *cal, boxes, frameW, frameH, cfg.maxCandidates,
				       pyramid, classifier, rejectStatic_ ? &static_ : nullptr, pool);
	return Status::success();
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

Status DetectorImpl::detect(const ImageView &image, Detections &out)
{
	out = Detections();
	stats = FrameStats();
	Status st = checkImage(image);
	if (!st.ok())
		return st;
	const auto tStart = StageClock::now();

	// Input: the frame as the camera gave it (the static scene reads it), then resized.
	FrameInput &frame = input_.begin(image);
	if (rejectStatic_)
		static_.observe(frame); // its time counts as "other"
	const auto tResize = StageClock::now();
	st = input_.resize();
	if (!st.ok())
		return st;
	stats.msResize = msSince(tResize);

	// Search: each pass demands from the pyramid what its windows read, and classifies
	// them (the generic method: the whole pyramid, every window).
	candidates_.clear();
	pyramid.beginFrame();
	if (calibrated_) {
		calibratedSearch.beginFrame(stats);
		st = calibratedSearch.run(frame, pyramid, classifier, candidates_, stats);
	} else {
		st = searchEveryWindow(frame, pyramid, classifier, candidates_, stats,
				       pool_.size() > 1 ? &pool_ : nullptr);
	}
	if (!st.ok())
		return st;

	// Suppression, then the dense regions take the detections (before static rejection:
	// a region around static structure stays, its windows are found again anyway; only
	// the output drops it), then world coordinates.
	const auto tNms = StageClock::now();
	Detection *boxes = candidates_.data();
	int kept = suppression_.run(boxes, candidates_.count());
	if (calibrated_)
		calibratedSearch.endFrame(boxes, kept, stats);
	if (rejectStatic_) {
		const int before = kept;
		kept = static_.reject(boxes, kept);
		stats.staticRejected = before - kept;
		static_.update();
	}
	if (hasCamera_)
		addWorldCoordinates(camera_, boxes, kept);
	stats.msNms = msSince(tNms);

	stats.computedLevels = pyramid.computedCount;
	stats.msChannels = pyramid.msChannels;
	stats.msApprox = pyramid.msApprox() + pyramid.msSmooth() + pyramid.msFilter();
	stats.msTotal = msSince(tStart);
	out.items = boxes;
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
