// SPDX-License-Identifier: BSD-2-Clause
// tests/capi/reference.h as a program, for the Python binding's test
// (tests/python/test_calped.py):
//   capi_reference model                  path of the converted INRIA model (exit 77: none)
//   capi_reference synthetic-model OUT    a small valid model blob
//   capi_reference frame K OUT.ppm        PETS frame K as binary PPM (exit 77: not fetched)
//   capi_reference detect MODEL PPM [--camera FILE] [--resize R] [--method generic|calibrated]
//                                         the C++ API's detections, one per line (%.9g)
#include "reference.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

int usage()
{
	std::fprintf(stderr, "usage: capi_reference model | synthetic-model OUT | frame K OUT.ppm | "
			     "detect MODEL PPM [--camera FILE] [--resize R] [--method generic|calibrated]\n");
	return 2;
}

int detect(int argc, char **argv)
{
	const char *camera = nullptr;
	double resize = 1.0;
	bool calibrated = false;
	for (int i = 4; i < argc; i += 2) {
		if (i + 1 >= argc)
			return usage();
		const std::string opt = argv[i], value = argv[i + 1];
		if (opt == "--camera")
			camera = argv[i + 1];
		else if (opt == "--resize")
			resize = std::atof(value.c_str());
		else if (opt == "--method" && (value == "generic" || value == "calibrated"))
			calibrated = value == "calibrated";
		else
			return usage();
	}
	std::vector<char> out(1 << 20);
	const int rc = capi_reference_detect(argv[2], argv[3], camera, resize, calibrated, out.data(), out.size());
	if (rc == 0)
		std::fputs(out.data(), stdout);
	return rc;
}

} // namespace

int main(int argc, char **argv)
{
	const std::string cmd = argc > 1 ? argv[1] : "";
	if (cmd == "model" && argc == 2) {
		char path[4096];
		const int rc = capi_reference_inria_model(path, sizeof(path));
		if (rc == 0)
			std::printf("%s\n", path);
		return rc;
	}
	if (cmd == "synthetic-model" && argc == 3)
		return capi_reference_synthetic_model(argv[2]);
	if (cmd == "frame" && argc == 4)
		return capi_reference_pets_frame(std::atoi(argv[2]), argv[3]);
	if (cmd == "detect" && argc >= 4)
		return detect(argc, argv);
	return usage();
}
