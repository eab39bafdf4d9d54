// SPDX-License-Identifier: BSD-2-Clause
#include "reference.h"

#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/model.h>

#include "synthetic.h"
#include "test_data.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

using namespace calped;

namespace {

int failed(const std::string &what)
{
	std::fprintf(stderr, "capi reference: %s\n", what.c_str());
	return 1;
}

bool writeFile(const std::string &path, const std::string &header, const uint8_t *data, size_t size)
{
	std::FILE *f = std::fopen(path.c_str(), "wb");
	if (!f)
		return false;
	const bool ok = std::fwrite(header.data(), 1, header.size(), f) == header.size() &&
			std::fwrite(data, 1, size, f) == size;
	return std::fclose(f) == 0 && ok;
}

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

} // namespace

extern "C" int capi_reference_synthetic_model(const char *path)
{
	const std::vector<uint8_t> blob = serializeModel(test::randomModel(1, 16));
	return writeFile(path, "", blob.data(), blob.size()) ? 0 : failed(std::string("cannot write ") + path);
}

extern "C" int capi_reference_inria_model(char *path, size_t size)
{
	const std::string blob = test::inriaModelBlob();
	if (blob.empty()) {
		std::fprintf(stderr, "capi reference: no INRIA model (../shared or calped-convert missing)\n");
		return CAPI_REFERENCE_SKIP;
	}
	if (blob.size() >= size)
		return failed("model path too long");
	std::snprintf(path, size, "%s", blob.c_str());
	return 0;
}

extern "C" int capi_reference_pets_frame(int k, const char *ppm)
{
	const std::string png = test::petsFrame(k);
	if (png.empty()) {
		std::fprintf(stderr, "capi reference: PETS frame %d not fetched (scripts/fetch-pets.sh 50)\n", k);
		return CAPI_REFERENCE_SKIP;
	}
	test::RgbImage frame;
	if (!test::loadRgb(png, frame))
		return failed("cannot decode " + png);
	const std::string header = "P6\n" + std::to_string(frame.width) + " " + std::to_string(frame.height) + "\n255\n";
	return writeFile(ppm, header, frame.pixels.data(), frame.pixels.size()) ? 0
										: failed(std::string("cannot write ") + ppm);
}

extern "C" int capi_reference_detect(const char *modelPath, const char *ppm, const char *calibration, double resize,
				     int calibrated, char *out, size_t size)
{
	DetectorConfig config;
	CameraModel camera;
	Model model;
	test::RgbImage frame;
	std::vector<uint8_t> bytes;
	if (!test::readFile(modelPath, bytes))
		return failed(std::string("cannot read ") + modelPath);
	Status st = loadModel(bytes.data(), bytes.size(), model);
	if (!st.ok())
		return failed(st.message());
	if (calibration) {
		if (!test::readFile(calibration, bytes))
			return failed(std::string("cannot read ") + calibration);
		st = loadCalibration(reinterpret_cast<const char *>(bytes.data()), bytes.size(), calibration, camera);
		if (!st.ok())
			return failed(st.message());
		config.camera = &camera;
	}
	if (!readPpm(ppm, frame))
		return failed(std::string("cannot read the PPM ") + ppm);
	config.maxWidth = frame.width;
	config.maxHeight = frame.height;
	config.resize = resize;
	config.method = calibrated ? DetectionMethod::Calibrated : DetectionMethod::Generic;
	std::unique_ptr<Detector> detector;
	Detections found;
	st = Detector::create(model, config, detector);
	if (st.ok())
		st = detector->detect(ImageView::rgb8(frame.pixels.data(), frame.width, frame.height), found);
	if (!st.ok())
		return failed(st.message());
	size_t used = 0;
	out[0] = 0;
	for (const Detection &d : found) {
		const int n = std::snprintf(out + used, size - used, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n",
					    double(d.x), double(d.y), double(d.w), double(d.h), double(d.score),
					    double(d.groundX), double(d.groundY), double(d.worldHeight));
		if (n < 0 || size_t(n) >= size - used)
			return failed("detections do not fit the buffer");
		used += size_t(n);
	}
	return 0;
}
