/* SPDX-License-Identifier: BSD-2-Clause */
/*
 * The C++ side of the C API's tests, callable from C (tests/capi/reference.cpp): what the
 * C++ API detects, and test inputs as files a C program or numpy reads without an image
 * decoder. In-process, so the C test needs no child process (none can be started from an
 * emulated program without binfmt_misc). Each returns 0, 77 when an input is not there
 * (../shared, calped-convert, the PETS frames; the reason on stderr), or 1 on failure.
 */
#ifndef CALPED_TESTS_CAPI_REFERENCE_H
#define CALPED_TESTS_CAPI_REFERENCE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CAPI_REFERENCE_SKIP 77

/* A small valid model blob (random trees; no ../shared needed) written to `path`. */
int capi_reference_synthetic_model(const char *path);
/* The converted INRIA model's path (tests/common/test_data.h) into path[size]. */
int capi_reference_inria_model(char *path, size_t size);
/* PETS frame k (1-based) written as a binary PPM (P6, 255). */
int capi_reference_pets_frame(int k, const char *ppm);
/* The C++ API's detections for the PPM frame: the default configuration with frames of
 * its size, `resize`, the camera from `calibration` (NULL: none) and the generic or
 * calibrated method; one line per detection, "x y w h score ground_x ground_y
 * world_height" each %.9g, into out[size] (NUL-terminated; 1 if it does not fit). */
int capi_reference_detect(const char *model, const char *ppm, const char *calibration, double resize,
			  int calibrated, char *out, size_t size);

#ifdef __cplusplus
}
#endif

#endif
