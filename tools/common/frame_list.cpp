// SPDX-License-Identifier: BSD-2-Clause
#include "frame_list.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace calped::apps {

bool hasImageExtension(const std::string &path)
{
	std::string ext = fs::path(path).extension().string();
	std::transform(ext.begin(), ext.end(), ext.begin(),
		       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
	return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".ppm" || ext == ".pgm";
}

namespace {

bool listFolder(const std::string &dir, std::vector<std::string> &frames, std::string &error)
{
	std::vector<std::string> names;
	std::error_code ec;
	fs::directory_iterator it(dir, ec), end;
	for (; !ec && it != end; it.increment(ec)) {
		std::error_code typeEc;
		if (!it->is_regular_file(typeEc)) // follows symlinks
			continue;
		std::string name = it->path().filename().string();
		if (hasImageExtension(name))
			names.push_back(name);
	}
	if (ec) {
		error = "cannot list folder " + dir + ": " + ec.message();
		return false;
	}
	if (names.empty()) {
		error = "no images (*.png, *.jpg, *.jpeg, *.ppm, *.pgm) in folder " + dir;
		return false;
	}
	std::sort(names.begin(), names.end());
	for (const std::string &name : names)
		frames.push_back((fs::path(dir) / name).string());
	return true;
}

} // namespace

bool listFrames(const std::vector<std::string> &inputs, std::vector<std::string> &frames,
		std::string &error)
{
	frames.clear();
	for (const std::string &input : inputs) {
		std::error_code ec;
		fs::file_status st = fs::status(input, ec);
		if (!fs::exists(st)) {
			error = "cannot read " + input + ": " +
				(ec && st.type() != fs::file_type::not_found ? ec.message()
									     : "no such file or folder");
			return false;
		}
		if (fs::is_directory(st)) {
			if (!listFolder(input, frames, error))
				return false;
		} else {
			frames.push_back(input);
		}
	}
	if (frames.empty()) {
		error = "no input frames";
		return false;
	}
	return true;
}

} // namespace calped::apps
