// SPDX-License-Identifier: BSD-2-Clause
// The C++ side of the C API and Python tests (tests/capi/capi_test.c,
// tests/python/test_calped.py): what the C++ API detects, and the test inputs in forms a
// C program or numpy reads without an image decoder.
//   capi_reference model                  path of the converted INRIA model (exit 77: none)
//   capi_reference synthetic-model OUT    a small valid model blob (no ../shared needed)
//   capi_reference frame K OUT.ppm        PETS frame K as binary PPM (exit 77: not fetched)
//   capi_reference detect MODEL PPM [--camera FILE] [--resize R] [--method generic|calibrated]
//                                         the C++ API's detections, one per line:
//                                         x y w h score ground_x ground_y world_height (%.9g)
#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/model.h>

#include "synthetic.h"
#include "test_data.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace calped;

namespace {

const int kSkip = 77;

int usage()
{
	std::fprintf(stderr, "usage: capi_reference model | synthetic-model OUT | frame K OUT.ppm | "
			     "detect MODEL PPM [--camera FILE] [--resize R] [--method generic|calibrated]\n");
	return 2;
}

bool writeFile(const std::string &path, const void *data, size_t size, const char *header = "")
{
	std::FILE *f = std::fopen(path.c_str(), "wb");
	if (!f)
		return false;
	const bool ok = std::fputs(header, f) >= 0 && std::fwrite(data, 1, size, f) == size;
	return std::fclose(f) == 0 && ok;
}

// Binary PPM (P6, maxval 255) as written by frame.
bool readPpm(const std::string &path, test::RgbImage &out)
{
	std::vector<uint8_t> bytes;
	if (!test::readFile(path, bytes))
		return false;
	int w = 0, h = 0, maxval = 0, used = 0;
	bytes.push_back(0);
	if (std::sscanf(reinterpret_cast<const char *>(bytes.data()), "P6 %d %d %d%n", &w, &h, &maxval, &used) != 3 ||
	    maxval != 255 || w <= 0 || h <= 0)
		return false;
	bytes.pop_back();
	const size_t start = size_t(used) + 1, n = size_t(w) * size_t(h) * 3;
	if (bytes.size() < start + n)
		return false;
	out.width = w;
	out.height = h;
	out.pixels.assign(bytes.begin() + long(start), bytes.begin() + long(start + n));
	return true;
}

int detect(int argc, char **argv)
{
	if (argc < 4)
		return usage();
	DetectorConfig config;
	CameraModel camera;
	for (int i = 4; i + 1 < argc; i += 2) {
		const std::string opt = argv[i], value = argv[i + 1];
		if (opt == "--camera") {
			std::vector<uint8_t> text;
			if (!test::readFile(value, text))
				return std::fprintf(stderr, "capi_reference: cannot read %s\n", value.c_str()), 1;
			const Status st = loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(),
							  value.c_str(), camera);
			if (!st.ok())
				return std::fprintf(stderr, "capi_reference: %s\n", st.message()), 1;
			config.camera = &camera;
		} else if (opt == "--resize") {
			config.resize = std::atof(value.c_str());
		} else if (opt == "--method") {
			config.method = value == "generic" ? DetectionMethod::Generic : DetectionMethod::Calibrated;
		} else {
			return usage();
		}
	}
	std::vector<uint8_t> blob;
	Model model;
	if (!test::readFile(argv[2], blob))
		return std::fprintf(stderr, "capi_reference: cannot read %s\n", argv[2]), 1;
	Status st = loadModel(blob.data(), blob.size(), model);
	test::RgbImage frame;
	if (st.ok() && !readPpm(argv[3], frame))
		return std::fprintf(stderr, "capi_reference: cannot read the PPM %s\n", argv[3]), 1;
	config.maxWidth = frame.width;
	config.maxHeight = frame.height;
	std::unique_ptr<Detector> detector;
	if (st.ok())
		st = Detector::create(model, config, detector);
	Detections found;
	if (st.ok())
		st = detector->detect(ImageView::rgb8(frame.pixels.data(), frame.width, frame.height), found);
	if (!st.ok())
		return std::fprintf(stderr, "capi_reference: %s\n", st.message()), 1;
	for (const Detection &d : found)
		std::printf("%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", double(d.x), double(d.y), double(d.w),
			    double(d.h), double(d.score), double(d.groundX), double(d.groundY), double(d.worldHeight));
	return 0;
}

} // namespace

int main(int argc, char **argv)
{
	if (argc < 2)
		return usage();
	const std::string cmd = argv[1];
	if (cmd == "model") {
		const std::string blob = test::inriaModelBlob();
		if (blob.empty())
			return std::fprintf(stderr, "capi_reference: no INRIA model (../shared or calped-convert missing)\n"),
			       kSkip;
		std::printf("%s\n", blob.c_str());
		return 0;
	}
	if (cmd == "synthetic-model" && argc == 3) {
		const std::vector<uint8_t> blob = serializeModel(test::randomModel(1, 16));
		return writeFile(argv[2], blob.data(), blob.size()) ? 0 : 1;
	}
	if (cmd == "frame" && argc == 4) {
		const std::string png = test::petsFrame(std::atoi(argv[2]));
		test::RgbImage frame;
		if (png.empty())
			return std::fprintf(stderr, "capi_reference: PETS frame %s not fetched (scripts/fetch-pets.sh)\n",
					    argv[2]),
			       kSkip;
		if (!test::loadRgb(png, frame))
			return std::fprintf(stderr, "capi_reference: cannot decode %s\n", png.c_str()), 1;
		const std::string header = "P6\n" + std::to_string(frame.width) + " " + std::to_string(frame.height) + "\n255\n";
		return writeFile(argv[3], frame.pixels.data(), frame.pixels.size(), header.c_str()) ? 0 : 1;
	}
	if (cmd == "detect")
		return detect(argc, argv);
	return usage();
}
