// SPDX-License-Identifier: BSD-2-Clause
#include "image_folder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>


namespace calped {
namespace ports {

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
		if (!isImageFileName(name))
			continue;
		// Named as a frame but not one: skipping it would renumber every later frame.
		std::error_code kindError;
		const fs::file_status kind = fs::status(it->path(), kindError);
		if (!fs::is_regular_file(kind))
			return Status::error(ErrorCode::IoError,
					     "%s is named like a frame but is %s, not a regular file",
					     name.c_str(),
					     fs::is_directory(kind) ? "a folder"
					     : fs::is_fifo(kind)    ? "a FIFO"
					     : !fs::exists(kind)    ? "a dangling symbolic link"
								    : "a device or socket");
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

Status probeImageFiles(ImageDecoder &decoder, const std::vector<std::string> &files,
		       int &maxWidth, int &maxHeight)
{
	maxWidth = maxHeight = 0;
	std::string error;
	for (const std::string &file : files) {
		int w = 0, h = 0;
		if (!decoder.probe(file, w, h, error))
			return Status::error(ErrorCode::IoError, "%s", error.c_str());
		maxWidth = std::max(maxWidth, w);
		maxHeight = std::max(maxHeight, h);
	}
	return Status::success();
}

Status decodeImageInto(ImageDecoder &decoder, const std::string &path, uint8_t *pixels,
		       size_t capacity, int &width, int &height)
{
	std::string error;
	if (!decoder.decodeInto(path, pixels, capacity, width, height, error))
		return Status::error(ErrorCode::IoError, "%s", error.c_str());
	return Status::success();
}

} // namespace ports
} // namespace calped
