/* SPDX-License-Identifier: BSD-2-Clause */
/*
 * The C API from C (compiled as C99): versions, error paths and their messages, and a
 * PETS frame whose detections must equal, to the last printed digit, those of the C++ API
 * for the same frame and configuration (printed by tests/capi/reference.cpp, linked in).
 *   capi_test WORKDIR
 * Environment (tests/meson.build): CALPED_SHARED_DIR (for View_001.xml) and what the
 * reference needs. Exit 0: all passed; 1: a check failed; 77: passed, but the PETS
 * comparison was skipped (no ../shared, model or frames; the reason is printed).
 */
#include <calped/calped_c.h>

#include "reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;
static const char *workdir;

#define CHECK(cond)                                                                        \
	do {                                                                               \
		if (!(cond)) {                                                             \
			fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
			failures++;                                                        \
		}                                                                          \
	} while (0)

/* The call failed with `code` and a message naming `needle`. */
static void expect_error(calped_status got, const calped_error *err, calped_status code, const char *needle,
			 const char *what)
{
	printf("  %-34s -> %s: %s\n", what, calped_status_name(got), err->message);
	if (got != code || err->code != (int)code) {
		fprintf(stderr, "%s: expected %s, got %s\n", what, calped_status_name(code), calped_status_name(got));
		failures++;
	}
	if (!strstr(err->message, needle)) {
		fprintf(stderr, "%s: message \"%s\" does not name \"%s\"\n", what, err->message, needle);
		failures++;
	}
	if (strncmp(err->message, calped_status_name(code), strlen(calped_status_name(code))) != 0) {
		fprintf(stderr, "%s: message does not start with the code's name\n", what);
		failures++;
	}
}

static char *read_all(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	char *data = NULL;
	size_t n = 0, cap = 0, got;
	if (!f)
		return NULL;
	do {
		if (n == cap) {
			char *bigger;
			cap = cap ? 2 * cap : 65536;
			bigger = realloc(data, cap + 1);
			if (!bigger) {
				free(data);
				fclose(f);
				return NULL;
			}
			data = bigger;
		}
		got = fread(data + n, 1, cap - n, f);
		n += got;
	} while (got > 0);
	fclose(f);
	data[n] = 0;
	*size = n;
	return data;
}

/* A binary PPM (P6, 255), as capi_reference_pets_frame writes it. */
static unsigned char *read_ppm(const char *path, int *width, int *height)
{
	size_t size = 0;
	int maxval = 0, used = 0;
	char *data = read_all(path, &size);
	unsigned char *rgb;
	if (!data)
		return NULL;
	if (sscanf(data, "P6 %d %d %d%n", width, height, &maxval, &used) != 3 || maxval != 255 ||
	    size < (size_t)used + 1 + (size_t)*width * (size_t)*height * 3) {
		free(data);
		return NULL;
	}
	rgb = malloc((size_t)*width * (size_t)*height * 3);
	if (rgb)
		memcpy(rgb, data + used + 1, (size_t)*width * (size_t)*height * 3);
	free(data);
	return rgb;
}

static void test_version_and_names(void)
{
	printf("version %s\n", calped_version());
	CHECK(strcmp(calped_version(), CALPED_VERSION) == 0);
	CHECK(strcmp(calped_status_name(CALPED_OK), "Ok") == 0);
	CHECK(strcmp(calped_status_name(CALPED_ERR_MODEL_CHECKSUM), "ModelChecksum") == 0);
	CHECK(strcmp(calped_status_name(CALPED_ERR_END_OF_STREAM), "EndOfStream") == 0);
	CHECK(strcmp(calped_status_name(CALPED_ERR_INTERNAL), "Internal") == 0);
	CHECK(strcmp(calped_status_name(55), "Unknown") == 0);
}

static void test_load_errors(const char *model_path)
{
	calped_error err;
	calped_model *model = (calped_model *)1;
	calped_camera *camera = (calped_camera *)1;
	char path[1024];
	size_t size = 0;
	char *blob;
	calped_status st;
	static const char garbage[] = "this is not a calped model blob, nor a calibration";

	printf("load errors\n");
	snprintf(path, sizeof(path), "%s/no-such-model.cpm", workdir);
	st = calped_model_load_file(path, &model, &err);
	expect_error(st, &err, CALPED_ERR_IO, "no-such-model.cpm", "model: missing file");
	CHECK(model == NULL);

	st = calped_model_load_memory(garbage, sizeof(garbage), &model, &err);
	expect_error(st, &err, CALPED_ERR_MODEL_BAD_MAGIC, "ModelBadMagic", "model: not a blob");
	st = calped_model_load_memory(NULL, 0, &model, &err);
	expect_error(st, &err, CALPED_ERR_MODEL_TRUNCATED, "ModelTruncated", "model: empty");
	st = calped_model_load_file(NULL, &model, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "NULL", "model: NULL path");

	blob = read_all(model_path, &size);
	CHECK(blob != NULL && size > 64);
	if (blob) {
		st = calped_model_load_memory(blob, size / 2, &model, &err);
		expect_error(st, &err, CALPED_ERR_MODEL_TRUNCATED, "ModelTruncated", "model: half a blob");
		blob[size - 1] ^= 0x55; /* the payload's last byte */
		st = calped_model_load_memory(blob, size, &model, &err);
		expect_error(st, &err, CALPED_ERR_MODEL_CHECKSUM, "CRC", "model: a corrupt byte");
		CHECK(model == NULL);
		free(blob);
	}

	snprintf(path, sizeof(path), "%s/no-such-calibration.xml", workdir);
	st = calped_camera_load_file(path, &camera, &err);
	expect_error(st, &err, CALPED_ERR_IO, "no-such-calibration.xml", "camera: missing file");
	CHECK(camera == NULL);
	st = calped_camera_load_memory("<Camera name=\"x\">\n<Geometry width=", 35, "broken.xml", &camera, &err);
	expect_error(st, &err, CALPED_ERR_PARSE, "broken.xml", "camera: malformed XML");
}

static void test_config(const calped_model *model)
{
	calped_config cfg;
	calped_error err;
	calped_detector *det = (calped_detector *)1;
	calped_status st;

	printf("configuration errors\n");
	calped_config_defaults(&cfg);
	CHECK(cfg.struct_size == sizeof(calped_config));
	CHECK(cfg.method == CALPED_METHOD_AUTO && cfg.resize == 1.0 && isnan(cfg.cascade_threshold));
	CHECK(calped_config_validate(&cfg, NULL, &err) == CALPED_OK && err.code == (int)CALPED_OK);

	cfg.max_candidates = 0;
	st = calped_detector_create(model, NULL, &cfg, &det, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "maxCandidates", "config: max_candidates 0");
	CHECK(det == NULL);

	calped_config_defaults(&cfg);
	CHECK(cfg.threads == 1);
	cfg.threads = 65;
	st = calped_detector_create(model, NULL, &cfg, &det, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "threads 65", "config: threads 65");
	CHECK(det == NULL);

	calped_config_defaults(&cfg);
	cfg.method = CALPED_METHOD_CALIBRATED;
	st = calped_config_validate(&cfg, NULL, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "camera", "config: calibrated, no camera");

	calped_config_defaults(&cfg);
	cfg.method = CALPED_METHOD_GENERIC;
	cfg.min_person_height = 1.2;
	st = calped_config_validate(&cfg, NULL, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "generic", "config: calibrated setting, generic");

	calped_config_defaults(&cfg);
	cfg.static_rejection = 1;
	cfg.static_difference = 0;
	st = calped_config_validate(&cfg, NULL, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "staticRejection.difference", "config: static difference 0");

	calped_config_defaults(&cfg);
	cfg.struct_size = 8;
	st = calped_detector_create(model, NULL, &cfg, &det, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "struct_size", "config: foreign struct_size");
}

static void test_frame_errors(const calped_model *model)
{
	calped_config cfg;
	calped_error err;
	calped_detector *det = NULL;
	const calped_detection *dets = (const calped_detection *)1;
	int count = -1;
	calped_image im;
	calped_status st;
	unsigned char *pixels = calloc(800 * 600 * 3, 1);

	printf("frame errors\n");
	calped_config_defaults(&cfg);
	cfg.max_width = 640;
	cfg.max_height = 480;
	CHECK(pixels != NULL);
	CHECK(calped_detector_create(model, NULL, &cfg, &det, &err) == CALPED_OK);
	if (!det || !pixels) {
		free(pixels);
		return;
	}
	memset(&im, 0, sizeof(im));
	im.planes[0] = pixels;
	im.width = 800;
	im.height = 600;
	im.format = CALPED_PIXEL_RGB8;
	st = calped_detect(det, &im, &dets, &count, &err);
	expect_error(st, &err, CALPED_ERR_IMAGE_TOO_LARGE, "800", "frame larger than the maximum");
	CHECK(dets == NULL && count == 0);

	im.width = 30;
	im.height = 60;
	st = calped_detect(det, &im, &dets, &count, &err);
	expect_error(st, &err, CALPED_ERR_IMAGE_TOO_SMALL, "ImageTooSmall", "frame below the model window");

	im.width = 640;
	im.height = 480;
	im.format = CALPED_PIXEL_NV12; /* no UV plane */
	st = calped_detect(det, &im, &dets, &count, &err);
	expect_error(st, &err, CALPED_ERR_IMAGE_EMPTY, "NV12", "NV12 without its UV plane");

	im.format = 42;
	st = calped_detect(det, &im, &dets, &count, &err);
	expect_error(st, &err, CALPED_ERR_UNSUPPORTED_PIXEL_FORMAT, "UnsupportedPixelFormat", "unknown pixel format");

	im.format = CALPED_PIXEL_GRAY8;
	im.strides[0] = 100;
	st = calped_detect(det, &im, &dets, &count, &err);
	expect_error(st, &err, CALPED_ERR_INVALID_ARGUMENT, "stride", "stride below the row");

	/* A black grey frame, packed (stride 0): runs, finds nothing. */
	im.strides[0] = 0;
	CHECK(calped_detect(det, &im, &dets, &count, &err) == CALPED_OK);
	CHECK(count == 0 && dets != NULL);
	CHECK(calped_detect(det, NULL, &dets, &count, &err) == CALPED_ERR_INVALID_ARGUMENT);
	calped_detector_free(det);
	free(pixels);
}

/* Detections printed as capi_reference_detect prints the C++ API's. */
static int print_detections(const calped_detection *d, int count, char *out, size_t size)
{
	size_t used = 0;
	int i;
	out[0] = 0;
	for (i = 0; i < count && used < size; i++)
		used += (size_t)snprintf(out + used, size - used, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", d[i].x,
					 d[i].y, d[i].w, d[i].h, d[i].score, d[i].ground_x, d[i].ground_y,
					 d[i].world_height);
	return used < size;
}

/* 1: compared (failures counted); 0: skipped (reason printed). */
static int test_pets(const char *model_path)
{
	char ppm[1024], calib[1024], *ours, *theirs;
	const char *shared = getenv("CALPED_SHARED_DIR");
	calped_model *model = NULL;
	calped_camera *camera = NULL;
	calped_detector *det = NULL;
	calped_config cfg;
	calped_error err;
	calped_stats stats;
	const calped_detection *dets = NULL;
	int count = 0, width = 0, height = 0, run;
	unsigned char *rgb;
	FILE *f;

	printf("PETS frame 1, calibrated (resize 2), and generic\n");
	snprintf(ppm, sizeof(ppm), "%s/capi-frame-000001.ppm", workdir);
	if (capi_reference_pets_frame(1, ppm) != 0) {
		printf("SKIP: PETS frame 1 is not there (scripts/fetch-pets.sh 50)\n");
		return 0;
	}
	snprintf(calib, sizeof(calib), "%s/data/pets2009-s2l1/View_001.xml", shared ? shared : "../shared");
	f = fopen(calib, "rb");
	if (!f) {
		printf("SKIP: no calibration %s (../shared missing)\n", calib);
		return 0;
	}
	fclose(f);
	rgb = read_ppm(ppm, &width, &height);
	CHECK(rgb != NULL);
	if (!rgb)
		return 1;
	CHECK(calped_model_load_file(model_path, &model, &err) == CALPED_OK);
	CHECK(calped_camera_load_file(calib, &camera, &err) == CALPED_OK);
	ours = malloc(1 << 16);
	theirs = malloc(1 << 16);
	for (run = 0; run < 2 && model && camera && ours && theirs; run++) {
		const int calibrated = run == 0;
		calped_config_defaults(&cfg);
		cfg.max_width = width;
		cfg.max_height = height;
		if (calibrated) {
			cfg.resize = 2.0;
			cfg.method = CALPED_METHOD_CALIBRATED;
		} else {
			cfg.method = CALPED_METHOD_GENERIC;
		}
		CHECK(calped_detector_create(model, calibrated ? camera : NULL, &cfg, &det, &err) == CALPED_OK);
		if (!det)
			break;
		CHECK((int)calped_detector_method(det) == cfg.method);
		{
			calped_image im;
			memset(&im, 0, sizeof(im));
			im.planes[0] = rgb;
			im.width = width;
			im.height = height;
			im.format = CALPED_PIXEL_RGB8;
			CHECK(calped_detect(det, &im, &dets, &count, &err) == CALPED_OK);
		}
		CHECK(calped_detector_stats(det, &stats, &err) == CALPED_OK);
		printf("  %s: %d detections, %llu windows, %.1f ms\n", calibrated ? "calibrated" : "generic", count,
		       (unsigned long long)stats.windows, stats.ms_total);
		CHECK(count > 0 && stats.windows > 0 && stats.ms_total > 0);
		CHECK(print_detections(dets, count, ours, 1 << 16));
		if (count > 0)
			CHECK(calibrated ? !isnan(dets[0].world_height) : isnan(dets[0].world_height));

		CHECK(capi_reference_detect(model_path, ppm, calibrated ? calib : NULL, cfg.resize, calibrated, theirs,
					    1 << 16) == 0);
		if (strcmp(ours, theirs) != 0) {
			fprintf(stderr, "C API detections differ from the C++ API's:\n--- C\n%s--- C++\n%s", ours, theirs);
			failures++;
		}
		calped_detector_free(det);
		det = NULL;
	}
	/* With a camera, the detector and every frame are the calibration's size. */
	if (model && camera) {
		calped_config_defaults(&cfg);
		cfg.max_width = 640;
		cfg.max_height = 480;
		expect_error(calped_detector_create(model, camera, &cfg, &det, &err), &err, CALPED_ERR_INVALID_ARGUMENT,
			     "768x576", "camera: detector of another size");
		/* The detector copies the model and camera: freed first, it still runs. */
		cfg.max_width = width;
		cfg.max_height = height;
		cfg.resize = 2.0;
		CHECK(calped_detector_create(model, camera, &cfg, &det, &err) == CALPED_OK);
	}
	calped_model_free(model);
	calped_camera_free(camera);
	if (det) {
		calped_image im;
		memset(&im, 0, sizeof(im));
		im.planes[0] = rgb;
		im.strides[0] = 3 * width;
		im.width = 640; /* a crop: not the calibration's size */
		im.height = 480;
		expect_error(calped_detect(det, &im, &dets, &count, &err), &err, CALPED_ERR_INVALID_ARGUMENT,
			     "768x576 frames, got 640x480", "camera: frame of another size");
		im.width = width;
		im.height = height;
		CHECK(calped_detect(det, &im, &dets, &count, &err) == CALPED_OK);
		CHECK(count > 0);
		calped_detector_free(det);
	}
	free(ours);
	free(theirs);
	free(rgb);
	return 1;
}

int main(int argc, char **argv)
{
	char model_path[1024], synthetic[1024];
	calped_model *model = NULL;
	calped_error err;
	int compared = 0;

	if (argc != 2) {
		fprintf(stderr, "usage: capi_test WORKDIR\n");
		return 2;
	}
	workdir = argv[1];

	test_version_and_names();

	/* The error paths need a model, not a trained one: a small synthetic blob. */
	snprintf(synthetic, sizeof(synthetic), "%s/capi-synthetic.cpm", workdir);
	CHECK(capi_reference_synthetic_model(synthetic) == 0);
	test_load_errors(synthetic);
	CHECK(calped_model_load_file(synthetic, &model, &err) == CALPED_OK);
	if (model) {
		test_config(model);
		test_frame_errors(model);
		calped_model_free(model);
	}

	if (capi_reference_inria_model(model_path, sizeof(model_path)) == 0)
		compared = test_pets(model_path);
	else
		printf("SKIP: no INRIA model (../shared/models or calped-convert missing)\n");

	if (failures) {
		printf("%d checks failed\n", failures);
		return 1;
	}
	printf(compared ? "all passed\n" : "passed; the PETS comparison was skipped\n");
	return compared ? 0 : 77;
}
