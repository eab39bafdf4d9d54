// SPDX-License-Identifier: BSD-2-Clause
#include "image_folder.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <stb_image.h>

namespace calped {
namespace ports {

namespace {

const char *stbReason()
{
	const char *r = stbi_failure_reason();
	return r ? r : "unknown format";
}

} // namespace

bool isImageFileName(const std::string &path)
{
	const size_t dot = path.rfind('.');
	if (dot == std::string::npos)
		return false;
	std::string ext = path.substr(dot + 1);
	for (char &c : ext)
		c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "ppm" || ext == "pgm";
}

Status listImageFiles(const std::string &path, std::vector<std::string> &files)
{
	namespace fs = std::filesystem;
	files.clear();
	std::error_code ec;
	const fs::file_status st = fs::status(path, ec);
	if (ec || !fs::exists(st))
		return Status::error(ErrorCode::IoError, "%s: no such file or folder", path.c_str());
	if (!fs::is_directory(st)) {
		files.push_back(path);
		return Status::success();
	}
	for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
		const std::string name = it->path().string();
		if (isImageFileName(name) && it->is_regular_file(ec))
			files.push_back(name);
	}
	if (ec)
		return Status::error(ErrorCode::IoError, "cannot list %s: %s", path.c_str(),
				     ec.message().c_str());
	if (files.empty())
		return Status::error(ErrorCode::IoError,
				     "%s has no .png, .jpg, .jpeg, .ppm or .pgm files", path.c_str());
	std::sort(files.begin(), files.end());
	return Status::success();
}

Status probeImageFiles(const std::vector<std::string> &files, int &maxWidth, int &maxHeight)
{
	maxWidth = maxHeight = 0;
	for (const std::string &file : files) {
		FILE *f = std::fopen(file.c_str(), "rb");
		if (!f)
			return Status::error(ErrorCode::IoError, "cannot read %s: %s", file.c_str(),
					     std::strerror(errno));
		int w = 0, h = 0, comp = 0;
		const bool ok = stbi_info_from_file(f, &w, &h, &comp) != 0;
		std::fclose(f);
		if (!ok || w <= 0 || h <= 0)
			return Status::error(ErrorCode::IoError, "cannot decode %s: %s", file.c_str(),
					     ok ? "empty image" : stbReason());
		maxWidth = std::max(maxWidth, w);
		maxHeight = std::max(maxHeight, h);
	}
	return Status::success();
}

Status decodeImageInto(const std::string &path, uint8_t *pixels, size_t capacity, int &width,
		       int &height)
{
	FILE *f = std::fopen(path.c_str(), "rb");
	if (!f)
		return Status::error(ErrorCode::IoError, "cannot read %s: %s", path.c_str(),
				     std::strerror(errno));
	int w = 0, h = 0, comp = 0;
	// Three channels requested: stb expands grey and drops alpha.
	stbi_uc *data = stbi_load_from_file(f, &w, &h, &comp, 3);
	std::fclose(f);
	if (!data)
		return Status::error(ErrorCode::IoError, "cannot decode %s: %s", path.c_str(),
				     stbReason());
	const size_t bytes = static_cast<size_t>(w) * h * 3;
	if (bytes > capacity) {
		stbi_image_free(data);
		// The file changed since it was probed.
		return Status::error(ErrorCode::IoError, "%s grew to %dx%d since it was opened",
				     path.c_str(), w, h);
	}
	std::memcpy(pixels, data, bytes);
	stbi_image_free(data);
	width = w;
	height = h;
	return Status::success();
}

} // namespace ports
} // namespace calped
