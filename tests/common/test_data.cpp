// SPDX-License-Identifier: BSD-2-Clause
#include "test_data.h"

#include "synthetic.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include <stb/stb_image.h>

namespace calped {
namespace test {

namespace {

bool exists(const std::string &path)
{
	struct stat st;
	return stat(path.c_str(), &st) == 0;
}

std::string env(const char *name)
{
	const char *v = std::getenv(name);
	return v ? v : "";
}

} // namespace

std::string sharedDir()
{
	std::string dir = env("CALPED_SHARED_DIR");
	if (dir.empty())
		dir = "../shared";
	return exists(dir + "/reference/dollar-toolbox-pets/README.md") ? dir : "";
}

std::string petsFrame(int k)
{
	std::string root = env("CALPED_SOURCE_DIR");
	if (root.empty())
		root = ".";
	char name[32];
	std::snprintf(name, sizeof(name), "/%06d.png", k);
	const std::string path = root + "/data/pets/frames" + name;
	return exists(path) ? path : "";
}

std::string inriaModelBlob()
{
	return toolboxModelBlob("AcfInriaDetector");
}

std::string toolboxModelBlob(const std::string &name)
{
	// The INRIA blob keeps its old name: other tests and benchmarks know it.
	const std::string file = name == "AcfInriaDetector" ? "inria-test" : name + "-test";
	const std::string blob = env("CALPED_BUILD_DIR") + "/tests/" + file + ".cpm";
	if (exists(blob))
		return blob;
	const std::string shared = sharedDir();
	const std::string convert = env("CALPED_CONVERT");
	if (shared.empty() || convert.empty() || !exists(convert))
		return "";
	// Several test programs may run at once: convert to a file of our own, then rename,
	// which is atomic, so nobody reads a half-written blob.
	const std::string tmp = blob + "." + std::to_string(getpid());
	const std::string cmd = "'" + convert + "' '" + shared +
				"/models/dollar-toolbox/" + name + ".mat' '" + tmp +
				"' > /dev/null";
	if (std::system(cmd.c_str()) != 0 || std::rename(tmp.c_str(), blob.c_str()) != 0) {
		std::remove(tmp.c_str());
		return "";
	}
	return exists(blob) ? blob : "";
}

bool loadRgb(const std::string &path, RgbImage &out)
{
	int w, h, n;
	uint8_t *data = stbi_load(path.c_str(), &w, &h, &n, 3);
	if (!data)
		return false;
	out.width = w;
	out.height = h;
	out.pixels.assign(data, data + size_t(w) * h * 3);
	stbi_image_free(data);
	return true;
}

bool readFile(const std::string &path, std::vector<uint8_t> &out)
{
	std::ifstream f(path, std::ios::binary);
	if (!f)
		return false;
	out.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
	return true;
}

std::vector<float> readFloats(const std::string &path)
{
	std::vector<uint8_t> bytes;
	std::vector<float> out;
	if (!readFile(path, bytes))
		return out;
	out.resize(bytes.size() / 4);
	for (size_t i = 0; i < out.size(); i++) {
		uint32_t u = uint32_t(bytes[4 * i]) | uint32_t(bytes[4 * i + 1]) << 8 |
			     uint32_t(bytes[4 * i + 2]) << 16 | uint32_t(bytes[4 * i + 3]) << 24;
		float f;
		static_assert(sizeof(f) == sizeof(u), "float is 32 bits");
		std::memcpy(&f, &u, 4);
		out[i] = f;
	}
	return out;
}

DiffStats compare(const float *ours, const float *ref, size_t n)
{
	DiffStats s;
	if (n == 0)
		return s;
	std::vector<double> d(n);
	for (size_t i = 0; i < n; i++) {
		d[i] = std::fabs(double(ours[i]) - double(ref[i]));
		s.meanAbs += d[i];
		s.meanA += ref[i];
		s.maxA = std::max(s.maxA, double(ref[i]));
		s.maxAbs = std::max(s.maxAbs, d[i]);
	}
	s.meanAbs /= n;
	s.meanA /= n;
	std::sort(d.begin(), d.end());
	s.p99Abs = d[std::min(n - 1, size_t(std::ceil(0.99 * n)) - 1)];
	return s;
}

bool loadFrameOrSynthetic(const std::string &path, const char *program, RgbImage &out)
{
	if (path.empty()) {
		out.width = 768;
		out.height = 576;
		out.pixels = randomImage(1, out.width, out.height);
		return true;
	}
	if (loadRgb(path, out))
		return true;
	std::fprintf(stderr, "%s: cannot decode %s\n", program, path.c_str());
	return false;
}

} // namespace test
} // namespace calped
