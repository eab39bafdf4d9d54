/* SPDX-License-Identifier: BSD-2-Clause */
/*
 * calped's C API: the pedestrian detector for C programs and foreign-function interfaces
 * (the Python binding, python/calped, is built on it). A thin layer over the C++ API
 * (calped/detector.h): the same detector, the same defaults, the same error codes and
 * messages, bit-identical detections. docs/c-api.md.
 *
 * Conventions:
 *  - Objects are opaque handles, created by a *_load_* or *_create function and released
 *    by the matching *_free function (which accepts NULL).
 *  - Every function that can fail returns a calped_status (CALPED_OK = 0) and, when its
 *    last argument `err` is not NULL, fills it with the code and a one-line message that
 *    starts with the code's name and names the offending file, field or size. Nothing
 *    else is written on failure (the *out handle is set to NULL). No function throws, no
 *    C++ type crosses this header, and there is no global or thread-local error state.
 *  - Thread safety: a detector is for one thread at a time (one detector per thread);
 *    models and cameras are immutable once loaded and may be shared by any number of
 *    detectors and threads. Every function is reentrant.
 *  - Memory: calped_detector_create allocates every buffer the largest configured frame
 *    needs; calped_detect borrows the caller's pixels and allocates nothing (except when
 *    a frame gives more detections than any before it, see calped_detect).
 */
#ifndef CALPED_CALPED_C_H
#define CALPED_CALPED_C_H

#include <stddef.h>
#include <stdint.h>

#include <calped/version.h>

#if defined(_WIN32)
#define CALPED_C_EXPORT __declspec(dllexport)
#elif defined(__GNUC__)
#define CALPED_C_EXPORT __attribute__((visibility("default")))
#else
#define CALPED_C_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Errors ------------------------------------------------------------------------ */

/* The C++ calped::ErrorCode values, in the same order and with the same numbers
 * (docs/errors.md says when each happens). */
typedef enum calped_status {
	CALPED_OK = 0,
	CALPED_ERR_INVALID_ARGUMENT,
	CALPED_ERR_UNSUPPORTED_PIXEL_FORMAT,
	CALPED_ERR_IMAGE_EMPTY,
	CALPED_ERR_IMAGE_TOO_LARGE,
	CALPED_ERR_IMAGE_TOO_SMALL,
	CALPED_ERR_MODEL_TRUNCATED,
	CALPED_ERR_MODEL_BAD_MAGIC,
	CALPED_ERR_MODEL_BAD_VERSION,
	CALPED_ERR_MODEL_CHECKSUM,
	CALPED_ERR_MODEL_INVALID,
	CALPED_ERR_MODEL_UNSUPPORTED,
	CALPED_ERR_OUT_OF_MEMORY,
	CALPED_ERR_IO,
	CALPED_ERR_PARSE,
	CALPED_ERR_CAMERA_NOT_FOUND,
	CALPED_ERR_CAMERA,
	CALPED_ERR_CAMERA_LOST,
	CALPED_ERR_TIMEOUT,
	CALPED_ERR_END_OF_STREAM,
	/* Not a C++ code: an unexpected C++ exception or a broken invariant caught at the
	 * boundary (a bug in calped; the message says what was caught). */
	CALPED_ERR_INTERNAL = 100
} calped_status;

/* The error of one call: the code and its message (always NUL-terminated). */
typedef struct calped_error {
	int code; /* a calped_status */
	char message[256];
} calped_error;

/* Name of a status code, e.g. "ModelChecksum" (the C++ errorCodeName), "Internal" for
 * CALPED_ERR_INTERNAL, "Unknown" for a value that is none of them. Never NULL; static. */
CALPED_C_EXPORT const char *calped_status_name(int code);

/* The library's version, CALPED_VERSION of the build (e.g. "0.1.0"); static. Compare
 * with the header's CALPED_VERSION to detect a library from another release. */
CALPED_C_EXPORT const char *calped_version(void);

/* ---- Model ------------------------------------------------------------------------- */

/* A classifier model (a calped model blob, docs/model-format.md; calped-convert makes
 * one from a toolbox .mat file). Immutable; may be shared between detectors and threads. */
typedef struct calped_model calped_model;

/* Reads and validates the blob at `path`. Errors: CALPED_ERR_INVALID_ARGUMENT (NULL path
 * or out), CALPED_ERR_IO (the file cannot be read; the message names it), the model codes
 * (truncated, bad magic, bad version, checksum, invalid, unsupported), out of memory. */
CALPED_C_EXPORT calped_status calped_model_load_file(const char *path, calped_model **out,
						     calped_error *err);

/* The same from `size` bytes at `data` (copied: the buffer may be freed on return). */
CALPED_C_EXPORT calped_status calped_model_load_memory(const void *data, size_t size,
						       calped_model **out, calped_error *err);

/* The model's name as stored in the blob (e.g. "AcfInriaDetector"); valid while the
 * model lives. "" for NULL. */
CALPED_C_EXPORT const char *calped_model_name(const calped_model *model);

/* Releases a model (NULL is ignored). Detectors created from it stay usable: they copy
 * what they need. */
CALPED_C_EXPORT void calped_model_free(calped_model *model);

/* ---- Camera ------------------------------------------------------------------------ */

/* A calibrated camera (docs/calibration.md): Tsai XML (PETS 2009), Oxford Town Centre
 * ".ci", a plain projection matrix or OpenCV YAML, the format detected from the content.
 * Immutable; may be shared. */
typedef struct calped_camera calped_camera;

/* Reads the calibration file at `path`. Errors: CALPED_ERR_INVALID_ARGUMENT (NULL path or
 * out; a calibration that is not a usable camera), CALPED_ERR_IO (cannot read the file),
 * CALPED_ERR_PARSE (malformed; the message names the file and line), out of memory. */
CALPED_C_EXPORT calped_status calped_camera_load_file(const char *path, calped_camera **out,
						      calped_error *err);

/* The same from memory; `name` (may be NULL) is the name messages give the input. */
CALPED_C_EXPORT calped_status calped_camera_load_memory(const void *data, size_t size,
							const char *name, calped_camera **out,
							calped_error *err);

/* The image size the calibration states (Tsai files do), else 0 x 0. Either pointer may
 * be NULL. */
CALPED_C_EXPORT void calped_camera_image_size(const calped_camera *camera, int *width,
					      int *height);

/* Releases a camera (NULL is ignored). Detectors keep their own copy. */
CALPED_C_EXPORT void calped_camera_free(calped_camera *camera);

/* ---- Detector configuration -------------------------------------------------------- */

/* calped::DetectionMethod: AUTO is calibrated with a camera, generic without one. */
typedef enum calped_method {
	CALPED_METHOD_AUTO = 0,
	CALPED_METHOD_GENERIC = 1,
	CALPED_METHOD_CALIBRATED = 2
} calped_method;

/* calped::ResizeAt: inside the pyramid (default, resize >= 1 only) or the frame first. */
typedef enum calped_resize_at {
	CALPED_RESIZE_AT_PYRAMID = 0,
	CALPED_RESIZE_AT_FRAME = 1
} calped_resize_at;

/* calped::PyramidLevels (calibrated method): levels placed for the camera, or the
 * toolbox's octaves. */
typedef enum calped_levels {
	CALPED_LEVELS_PLACED = 0,
	CALPED_LEVELS_TOOLBOX = 1
} calped_levels;

/* calped::DetectorConfig flattened; calped/detector.h documents each setting and
 * calped_config_defaults fills the C++ defaults. Boolean settings are int, 0 or not;
 * enumerated ones are int too (the enum named), so that any value a caller stores is
 * well defined and refused when it is none of the enum's (here and in calped_image).
 * The calibrated_* settings are the C++ CalibratedSettings: they are used when the
 * calibrated method runs; with the generic method they must keep their defaults (as the
 * C++ API refuses calibrated settings there). Error messages name the C++ fields
 * (maxCandidates, calibrated.minPersonHeight, ...); docs/c-api.md maps them. */
typedef struct calped_config {
	/* sizeof(calped_config), set by calped_config_defaults: a caller built against
	 * another layout of this struct is refused instead of misread. */
	uint32_t struct_size;
	/* Largest input frame, 1..16384 (default 1920 x 1080). With a camera, every frame
	 * must be exactly this size. */
	int max_width, max_height;
	double resize;           /* (0, 8], default 1 */
	int resize_at;           /* a calped_resize_at, default CALPED_RESIZE_AT_PYRAMID */
	int max_candidates;      /* 1..2^24, default 65536 */
	float cascade_threshold; /* NaN (default): the model's */
	int nms;                 /* default 1 */
	int method;              /* a calped_method, default CALPED_METHOD_AUTO */
	/* Calibrated settings (calped::CalibratedSettings). */
	double min_person_height, max_person_height; /* metres, default 1.4 and 2.2 */
	int sparse_dense;                            /* default 1 */
	int dense_region_persistence;                /* frames, default 3 */
	int max_dense_regions;                       /* default 256 */
	int score_ratio;                             /* default 0 */
	int box_voting;                              /* default 1 */
	int levels;                                  /* a calped_levels, default PLACED */
	int placed_level_reach;                      /* 1..16, default 5 */
	/* Static-scene rejection (calped::StaticRejection), off by default. */
	int static_rejection;
	int static_difference;         /* grey levels 1..254, default 10 */
	float static_min_foreground;   /* 0..1, default 0.1 */
	int static_warmup_frames;      /* >= 1, default 50 */
	/* Threads the detector works on, the calling one included: 1..64, default 1
	 * (calped::DetectorConfig::threads; the detections do not depend on it). */
	int threads;
} calped_config;

/* Fills *config with the defaults, exactly those of the C++ DetectorConfig,
 * CalibratedSettings and StaticRejection, and sets struct_size. Call it first, then
 * change what differs. NULL is ignored. */
CALPED_C_EXPORT void calped_config_defaults(calped_config *config);

/* Validates a configuration as calped_detector_create would (without a model), with
 * `camera` (may be NULL) as its camera. CALPED_ERR_INVALID_ARGUMENT names the first bad
 * setting. */
CALPED_C_EXPORT calped_status calped_config_validate(const calped_config *config,
						     const calped_camera *camera,
						     calped_error *err);

/* ---- Images ------------------------------------------------------------------------ */

/* calped::PixelFormat, same order and numbers (docs/pixel-formats.md). */
typedef enum calped_pixel_format {
	CALPED_PIXEL_RGB8 = 0,
	CALPED_PIXEL_BGR8,
	CALPED_PIXEL_GRAY8,
	CALPED_PIXEL_NV12,
	CALPED_PIXEL_YUV420,
	CALPED_PIXEL_YUYV,
	CALPED_PIXEL_BAYER_RGGB8,
	CALPED_PIXEL_BAYER_GRBG8,
	CALPED_PIXEL_BAYER_GBRG8,
	CALPED_PIXEL_BAYER_BGGR8
} calped_pixel_format;

/* calped::YuvEncoding (YUV formats only). */
typedef enum calped_yuv_encoding {
	CALPED_YUV_BT601_LIMITED = 0,
	CALPED_YUV_BT601_FULL,
	CALPED_YUV_BT709_LIMITED,
	CALPED_YUV_BT709_FULL
} calped_yuv_encoding;

/* A borrowed frame (calped::ImageView): the caller keeps the pixels alive and unchanged
 * while calped_detect runs. planes[0] is the only plane of one-plane formats (RGB8, BGR8,
 * GRAY8, YUYV, Bayer) and the Y plane of NV12 and YUV420; planes[1] is NV12's interleaved
 * UV plane or YUV420's U plane, planes[2] YUV420's V plane. Strides are in bytes; a
 * stride of 0 means tightly packed rows (width * bytes per pixel; chroma rows of 4:2:0
 * formats hold ceil(width / 2) samples). Zero-initialise, then fill what the format uses. */
typedef struct calped_image {
	const uint8_t *planes[3];
	int strides[3];
	int width, height;
	int format; /* a calped_pixel_format */
	int yuv;    /* a calped_yuv_encoding; 0 (default): BT.601 limited range */
} calped_image;

/* ---- Detector ---------------------------------------------------------------------- */

typedef struct calped_detector calped_detector;

/* One detection in input-image pixels (calped::Detection): top-left corner, size, score;
 * with a camera also where the person stands (world metres) and the box's world height
 * (metres), NaN without a camera or when the foot is above the horizon. */
typedef struct calped_detection {
	float x, y, w, h;
	float score;
	float ground_x, ground_y, world_height;
} calped_detection;

/* What the detector did on the last frame (calped::FrameStats, same meanings). */
typedef struct calped_stats {
	int levels, computed_levels;
	uint64_t windows, candidates, dropped_windows;
	uint64_t sparse_windows, dense_windows;
	int dense_regions;
	uint64_t dropped_regions;
	int static_rejected;
	uint64_t static_skipped;
	double ms_resize, ms_channels, ms_approx, ms_classify, ms_candidates, ms_nms, ms_total;
} calped_stats;

/* Creates a detector for `model` with `config` (NULL: the defaults) and an optional
 * `camera` (NULL: none; it is copied, as are the model's trees, so both may be freed
 * afterwards). Allocates every buffer the configured maximum frame needs. Errors:
 * CALPED_ERR_INVALID_ARGUMENT (NULL model or out, a struct_size that is not this
 * library's, a setting out of range: named), CALPED_ERR_MODEL_INVALID,
 * CALPED_ERR_MODEL_UNSUPPORTED, CALPED_ERR_OUT_OF_MEMORY. */
CALPED_C_EXPORT calped_status calped_detector_create(const calped_model *model,
						     const calped_camera *camera,
						     const calped_config *config,
						     calped_detector **out, calped_error *err);

/* Releases a detector (NULL is ignored) and the detections it returned. */
CALPED_C_EXPORT void calped_detector_free(calped_detector *detector);

/* Runs the detector on one frame. On success *detections points to *count detections
 * owned by the detector, valid until the next calped_detect or calped_detector_free on
 * it; on failure *detections is NULL and *count 0. Frames may change size and format
 * between calls within the configured maximum (with a camera they must be exactly the
 * configured size). Allocates only when a frame has more detections than any frame
 * before on this detector (at least 256 fit without). Errors: CALPED_ERR_INVALID_ARGUMENT
 * (NULL arguments, bad strides, an unknown YUV encoding), the image codes
 * (CALPED_ERR_UNSUPPORTED_PIXEL_FORMAT, CALPED_ERR_IMAGE_EMPTY, CALPED_ERR_IMAGE_TOO_LARGE,
 * CALPED_ERR_IMAGE_TOO_SMALL); the message names the format, plane or sizes. */
CALPED_C_EXPORT calped_status calped_detect(calped_detector *detector,
					    const calped_image *image,
					    const calped_detection **detections, int *count,
					    calped_error *err);

/* The last frame's statistics (zeros before the first frame). NULL arguments are
 * CALPED_ERR_INVALID_ARGUMENT. */
CALPED_C_EXPORT calped_status calped_detector_stats(const calped_detector *detector,
						    calped_stats *out, calped_error *err);

/* The method that runs (AUTO resolved by the camera); CALPED_METHOD_AUTO for NULL. */
CALPED_C_EXPORT calped_method calped_detector_method(const calped_detector *detector);

#ifdef __cplusplus
}
#endif

#endif /* CALPED_CALPED_C_H */
