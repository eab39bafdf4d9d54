// SPDX-License-Identifier: BSD-2-Clause
// The C API (calped/calped_c.h) over the C++ API. Every entry point catches everything:
// no exception crosses the boundary, and a failure always comes back as a code and a
// message in the caller's calped_error.
#include <calped/calped_c.h>

#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/image.h>
#include <calped/model.h>
#include <calped/status.h>
#include <calped/version.h>

#include "capped_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

struct calped_model {
	calped::Model model;
};

struct calped_camera {
	calped::CameraModel camera;
};

struct calped_detector {
	std::unique_ptr<calped::Detector> detector;
	std::vector<calped_detection> detections; // what the last calped_detect returned
};

namespace {

using calped::ErrorCode;
using calped::Status;
namespace files = calped::files;

// The C enums mirror the C++ ones value for value: checked here, once.
static_assert(int(CALPED_ERR_END_OF_STREAM) == int(ErrorCode::EndOfStream), "calped_status mirrors ErrorCode");
static_assert(int(CALPED_ERR_INVALID_ARGUMENT) == int(ErrorCode::InvalidArgument), "calped_status mirrors ErrorCode");
static_assert(int(CALPED_ERR_IO) == int(ErrorCode::IoError), "calped_status mirrors ErrorCode");
static_assert(int(CALPED_PIXEL_BAYER_BGGR8) == int(calped::PixelFormat::BayerBGGR8), "calped_pixel_format mirrors PixelFormat");
static_assert(int(CALPED_PIXEL_NV12) == int(calped::PixelFormat::NV12), "calped_pixel_format mirrors PixelFormat");
static_assert(int(CALPED_YUV_BT709_FULL) == int(calped::YuvEncoding::Bt709Full), "calped_yuv_encoding mirrors YuvEncoding");
static_assert(int(CALPED_METHOD_CALIBRATED) == int(calped::DetectionMethod::Calibrated), "calped_method mirrors DetectionMethod");
static_assert(int(CALPED_RESIZE_AT_FRAME) == int(calped::ResizeAt::Frame), "calped_resize_at mirrors ResizeAt");
static_assert(int(CALPED_LEVELS_TOOLBOX) == int(calped::PyramidLevels::Toolbox), "calped_levels mirrors PyramidLevels");

calped_status fail(calped_error *err, const Status &st)
{
	const calped_status code = static_cast<calped_status>(st.code());
	if (err) {
		err->code = int(code);
		std::snprintf(err->message, sizeof(err->message), "%s", st.message());
	}
	return code;
}

calped_status fail(calped_error *err, ErrorCode code, const char *message)
{
	return fail(err, Status::error(code, "%s", message));
}

calped_status succeed(calped_error *err)
{
	if (err) {
		err->code = CALPED_OK;
		std::snprintf(err->message, sizeof(err->message), "ok");
	}
	return CALPED_OK;
}

// Runs `body` (which returns a calped_status and reports through err itself) and turns
// anything it throws into a status: the boundary never lets an exception out.
template <typename Body> calped_status guarded(calped_error *err, Body &&body) noexcept
{
	try {
		return body();
	} catch (const std::bad_alloc &) {
		return fail(err, ErrorCode::OutOfMemory, "out of memory");
	} catch (const std::exception &e) {
		if (err) {
			err->code = CALPED_ERR_INTERNAL;
			std::snprintf(err->message, sizeof(err->message), "Internal: %s", e.what());
		}
	} catch (...) {
		if (err) {
			err->code = CALPED_ERR_INTERNAL;
			std::snprintf(err->message, sizeof(err->message), "Internal: unknown exception");
		}
	}
	return CALPED_ERR_INTERNAL;
}

// The whole file, or IoError naming it: only a regular file, at most maxBytes (the
// programs' caps, fileio/capped_file.h), so a FIFO or /dev/zero cannot block or exhaust.
Status readFile(const char *path, const char *what, size_t maxBytes, std::vector<char> &out)
{
	std::vector<uint8_t> bytes;
	std::string error;
	if (!files::readFileBytes(path, bytes, error, what, maxBytes))
		return Status::error(ErrorCode::IoError, "%s", error.c_str());
	out.assign(bytes.begin(), bytes.end());
	return Status::success();
}

// The *_load_file functions: the arguments checked, the file read, then `load(bytes)`.
template <typename Handle, typename Load>
calped_status loadFile(const char *function, const char *what, size_t maxBytes, const char *path, Handle **out,
		       calped_error *err, Load &&load)
{
	return guarded(err, [&] {
		if (out)
			*out = nullptr;
		if (!path || !out)
			return fail(err, Status::error(ErrorCode::InvalidArgument, "%s: path and out must not be NULL", function));
		std::vector<char> bytes;
		const Status st = readFile(path, what, maxBytes, bytes);
		return st.ok() ? load(bytes) : fail(err, st);
	});
}

calped_status loadModel(const void *data, size_t size, calped_model **out, calped_error *err)
{
	if (!data && size > 0)
		return fail(err, ErrorCode::InvalidArgument, "model data is NULL with a non-zero size");
	std::unique_ptr<calped_model> m(new calped_model);
	static const uint8_t empty = 0;
	const Status st = calped::loadModel(data ? static_cast<const uint8_t *>(data) : &empty, size, m->model);
	if (!st.ok())
		return fail(err, st);
	*out = m.release();
	return succeed(err);
}

calped_status loadCamera(const char *data, size_t size, const char *name, calped_camera **out,
			 calped_error *err)
{
	if (!data && size > 0)
		return fail(err, ErrorCode::InvalidArgument, "calibration data is NULL with a non-zero size");
	std::unique_ptr<calped_camera> c(new calped_camera);
	const Status st = calped::loadCalibration(data ? data : "", size, name ? name : "calibration", c->camera);
	if (!st.ok())
		return fail(err, st);
	*out = c.release();
	return succeed(err);
}

// The C++ configuration a C one stands for. The calibrated settings are passed when the
// calibrated method runs, or when they differ from the defaults (so that the C++
// validation refuses them with the generic method, as it refuses them in C++).
Status toCpp(const calped_config *c, const calped_camera *camera, calped::DetectorConfig &out)
{
	if (c->struct_size != sizeof(calped_config))
		return Status::error(ErrorCode::InvalidArgument,
				     "calped_config.struct_size is %u, this library's is %u (fill the config with "
				     "calped_config_defaults)",
				     unsigned(c->struct_size), unsigned(sizeof(calped_config)));
	calped::DetectorConfig d;
	d.maxWidth = c->max_width;
	d.maxHeight = c->max_height;
	d.resize = c->resize;
	d.resizeAt = static_cast<calped::ResizeAt>(c->resize_at);
	d.maxCandidates = c->max_candidates;
	d.cascadeThreshold = c->cascade_threshold;
	d.nms = c->nms != 0;
	d.threads = c->threads;
	d.camera = camera ? &camera->camera : nullptr;
	d.method = static_cast<calped::DetectionMethod>(c->method);
	if (c->method < CALPED_METHOD_AUTO || c->method > CALPED_METHOD_CALIBRATED)
		return Status::error(ErrorCode::InvalidArgument, "method %d is not a calped_method", int(c->method));
	if (c->resize_at < CALPED_RESIZE_AT_PYRAMID || c->resize_at > CALPED_RESIZE_AT_FRAME)
		return Status::error(ErrorCode::InvalidArgument, "resize_at %d is not a calped_resize_at", int(c->resize_at));
	if (c->levels < CALPED_LEVELS_PLACED || c->levels > CALPED_LEVELS_TOOLBOX)
		return Status::error(ErrorCode::InvalidArgument, "levels %d is not a calped_levels", int(c->levels));

	calped::CalibratedSettings s;
	const calped::CalibratedSettings defaults;
	s.minPersonHeight = c->min_person_height;
	s.maxPersonHeight = c->max_person_height;
	s.sparseDense = c->sparse_dense != 0;
	s.denseRegionPersistence = c->dense_region_persistence;
	s.maxDenseRegions = c->max_dense_regions;
	s.scoreRatio = c->score_ratio != 0;
	s.boxVoting = c->box_voting != 0;
	s.levels = static_cast<calped::PyramidLevels>(c->levels);
	s.placedLevelReach = c->placed_level_reach;
	const bool isDefault = s.minPersonHeight == defaults.minPersonHeight &&
			       s.maxPersonHeight == defaults.maxPersonHeight &&
			       s.sparseDense == defaults.sparseDense &&
			       s.denseRegionPersistence == defaults.denseRegionPersistence &&
			       s.maxDenseRegions == defaults.maxDenseRegions && s.scoreRatio == defaults.scoreRatio &&
			       s.boxVoting == defaults.boxVoting && s.levels == defaults.levels &&
			       s.placedLevelReach == defaults.placedLevelReach;
	if (d.resolvedMethod() == calped::DetectionMethod::Calibrated || !isDefault)
		d.calibrated = s;

	if (c->static_rejection) {
		calped::StaticRejection r;
		r.difference = c->static_difference;
		r.minForeground = c->static_min_foreground;
		r.warmupFrames = c->static_warmup_frames;
		d.staticRejection = r;
	}
	out = d;
	return d.validate();
}

// Stride 0: tightly packed rows of the plane.
int packedStride(int format, int plane, int width)
{
	const int chroma = (width + 1) / 2;
	switch (format) {
	case CALPED_PIXEL_NV12:
		return plane == 0 ? width : 2 * chroma;
	case CALPED_PIXEL_YUV420:
		return plane == 0 ? width : chroma;
	default:
		return plane == 0 ? calped::ImageView::packedRowBytes(static_cast<calped::PixelFormat>(format), width)
				  : 0;
	}
}

calped::ImageView toView(const calped_image &im)
{
	calped::ImageView v;
	for (int p = 0; p < 3; p++) {
		v.planes[p] = im.planes[p];
		v.strides[p] = im.strides[p] ? im.strides[p] : packedStride(im.format, p, im.width);
	}
	v.width = im.width;
	v.height = im.height;
	v.format = static_cast<calped::PixelFormat>(im.format);
	v.yuv = static_cast<calped::YuvEncoding>(im.yuv);
	return v;
}

} // namespace

extern "C" {

const char *calped_status_name(int code)
{
	if (code == CALPED_ERR_INTERNAL)
		return "Internal";
	if (code < CALPED_OK || code > CALPED_ERR_END_OF_STREAM)
		return "Unknown";
	return calped::errorCodeName(static_cast<ErrorCode>(code));
}

const char *calped_version(void)
{
	return CALPED_VERSION;
}

calped_status calped_model_load_file(const char *path, calped_model **out, calped_error *err)
{
	return loadFile("calped_model_load_file", "model ", files::kMaxModelFileBytes, path, out, err, [&](const std::vector<char> &bytes) {
		return loadModel(bytes.data(), bytes.size(), out, err);
	});
}

calped_status calped_model_load_memory(const void *data, size_t size, calped_model **out, calped_error *err)
{
	return guarded(err, [&] {
		if (!out)
			return fail(err, ErrorCode::InvalidArgument, "calped_model_load_memory: out must not be NULL");
		*out = nullptr;
		return loadModel(data, size, out, err);
	});
}

const char *calped_model_name(const calped_model *model)
{
	return model ? model->model.name.c_str() : "";
}

void calped_model_free(calped_model *model)
{
	delete model;
}

calped_status calped_camera_load_file(const char *path, calped_camera **out, calped_error *err)
{
	return loadFile("calped_camera_load_file", "calibration ", files::kMaxCalibrationFileBytes, path, out, err, [&](const std::vector<char> &bytes) {
		return loadCamera(bytes.data(), bytes.size(), path, out, err);
	});
}

calped_status calped_camera_load_memory(const void *data, size_t size, const char *name, calped_camera **out,
					calped_error *err)
{
	return guarded(err, [&] {
		if (!out)
			return fail(err, ErrorCode::InvalidArgument, "calped_camera_load_memory: out must not be NULL");
		*out = nullptr;
		return loadCamera(static_cast<const char *>(data), size, name, out, err);
	});
}

void calped_camera_image_size(const calped_camera *camera, int *width, int *height)
{
	if (width)
		*width = camera ? camera->camera.imageWidth() : 0;
	if (height)
		*height = camera ? camera->camera.imageHeight() : 0;
}

void calped_camera_free(calped_camera *camera)
{
	delete camera;
}

void calped_config_defaults(calped_config *config)
{
	if (!config)
		return;
	const calped::DetectorConfig d;
	const calped::CalibratedSettings s;
	const calped::StaticRejection r;
	std::memset(config, 0, sizeof(*config));
	config->struct_size = sizeof(calped_config);
	config->max_width = d.maxWidth;
	config->max_height = d.maxHeight;
	config->resize = d.resize;
	config->resize_at = int(d.resizeAt);
	config->max_candidates = d.maxCandidates;
	config->cascade_threshold = d.cascadeThreshold;
	config->nms = d.nms;
	config->method = int(d.method);
	config->min_person_height = s.minPersonHeight;
	config->max_person_height = s.maxPersonHeight;
	config->sparse_dense = s.sparseDense;
	config->dense_region_persistence = s.denseRegionPersistence;
	config->max_dense_regions = s.maxDenseRegions;
	config->score_ratio = s.scoreRatio;
	config->box_voting = s.boxVoting;
	config->levels = int(s.levels);
	config->placed_level_reach = s.placedLevelReach;
	config->static_rejection = d.staticRejection.has_value();
	config->static_difference = r.difference;
	config->static_min_foreground = r.minForeground;
	config->static_warmup_frames = r.warmupFrames;
	config->threads = d.threads;
}

calped_status calped_config_validate(const calped_config *config, const calped_camera *camera,
				     calped_error *err)
{
	return guarded(err, [&] {
		if (!config)
			return fail(err, ErrorCode::InvalidArgument, "calped_config_validate: config must not be NULL");
		calped::DetectorConfig d;
		const Status st = toCpp(config, camera, d);
		return st.ok() ? succeed(err) : fail(err, st);
	});
}

calped_status calped_detector_create(const calped_model *model, const calped_camera *camera,
				     const calped_config *config, calped_detector **out, calped_error *err)
{
	return guarded(err, [&] {
		if (out)
			*out = nullptr;
		if (!model || !out)
			return fail(err, ErrorCode::InvalidArgument, "calped_detector_create: model and out must not be NULL");
		calped_config defaults;
		if (!config) {
			calped_config_defaults(&defaults);
			config = &defaults;
		}
		calped::DetectorConfig d;
		Status st = toCpp(config, camera, d);
		if (!st.ok())
			return fail(err, st);
		std::unique_ptr<calped_detector> det(new calped_detector);
		st = calped::Detector::create(model->model, d, det->detector);
		if (!st.ok())
			return fail(err, st);
		det->detections.resize(std::min(256, d.maxCandidates));
		*out = det.release();
		return succeed(err);
	});
}

void calped_detector_free(calped_detector *detector)
{
	delete detector;
}

calped_status calped_detect(calped_detector *detector, const calped_image *image,
			    const calped_detection **detections, int *count, calped_error *err)
{
	return guarded(err, [&] {
		if (detections)
			*detections = nullptr;
		if (count)
			*count = 0;
		if (!detector || !image || !detections || !count)
			return fail(err, ErrorCode::InvalidArgument,
				    "calped_detect: detector, image, detections and count must not be NULL");
		calped::Detections found;
		const Status st = detector->detector->detect(toView(*image), found);
		if (!st.ok())
			return fail(err, st);
		std::vector<calped_detection> &out = detector->detections;
		if (size_t(found.count) > out.size())
			out.resize(size_t(found.count));
		for (int i = 0; i < found.count; i++) {
			const calped::Detection &f = found.items[i];
			out[size_t(i)] = calped_detection{ f.x, f.y, f.w, f.h, f.score, f.groundX, f.groundY, f.worldHeight };
		}
		*detections = out.data();
		*count = found.count;
		return succeed(err);
	});
}

calped_status calped_detector_stats(const calped_detector *detector, calped_stats *out, calped_error *err)
{
	return guarded(err, [&] {
		if (!detector || !out)
			return fail(err, ErrorCode::InvalidArgument, "calped_detector_stats: detector and out must not be NULL");
		const calped::FrameStats &s = detector->detector->lastStats();
		*out = calped_stats{ s.levels,        s.computedLevels, s.windows,         s.candidates,     s.droppedWindows,
				     s.sparseWindows, s.denseWindows,   s.denseRegions,    s.droppedRegions, s.staticRejected,
				     s.staticSkipped, s.msResize,       s.msChannels,      s.msApprox,       s.msClassify,
				     s.msCandidates,  s.msNms,          s.msTotal };
		return succeed(err);
	});
}

calped_method calped_detector_method(const calped_detector *detector)
{
	if (!detector)
		return CALPED_METHOD_AUTO;
	return static_cast<calped_method>(detector->detector->config().method);
}

} // extern "C"
