// SPDX-License-Identifier: BSD-2-Clause
#include "image_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "file_io.h"

// Debian's libstb ships the compiled implementations; elsewhere stb_impl.cpp provides them.
#include <stb_image.h>
#include <stb_image_write.h>

namespace calped::detect_tool {

namespace {

struct FileCloser {
	void operator()(FILE *f) const { std::fclose(f); }
};

struct StbiFree {
	void operator()(stbi_uc *p) const { stbi_image_free(p); }
};

const char *stbReason()
{
	const char *r = stbi_failure_reason();
	return r ? r : "unknown format";
}

} // namespace

bool probeImage(const std::string &path, int &width, int &height, std::string &error)
{
	std::unique_ptr<FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
	if (!f) {
		error = "cannot read " + path + ": " + std::strerror(errno);
		return false;
	}
	int comp = 0;
	if (!stbi_info_from_file(f.get(), &width, &height, &comp)) {
		error = "cannot decode " + path + ": " + stbReason();
		return false;
	}
	if (width <= 0 || height <= 0) {
		error = "cannot decode " + path + ": empty image";
		return false;
	}
	return true;
}

bool decodeImage(const std::string &path, RgbImage &out, std::string &error)
{
	std::vector<uint8_t> bytes;
	if (!readFile(path, bytes, error))
		return false;
	if (bytes.empty() || bytes.size() > static_cast<size_t>(INT32_MAX)) {
		error = "cannot decode " + path + (bytes.empty() ? ": empty file" : ": file too large");
		return false;
	}
	int w = 0, h = 0, comp = 0;
	// Asking for 3 channels makes stb expand grey (and drop alpha).
	std::unique_ptr<stbi_uc, StbiFree> data(stbi_load_from_memory(
		bytes.data(), static_cast<int>(bytes.size()), &w, &h, &comp, 3));
	if (!data) {
		error = "cannot decode " + path + ": " + stbReason();
		return false;
	}
	out.width = w;
	out.height = h;
	out.pixels.assign(data.get(), data.get() + static_cast<size_t>(w) * h * 3);
	return true;
}

bool writePng(const std::string &path, const RgbImage &image, std::string &error)
{
	if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.pixels.data(),
			    image.width * 3)) {
		error = "cannot write " + path;
		return false;
	}
	return true;
}

} // namespace calped::detect_tool
