// SPDX-License-Identifier: BSD-2-Clause
#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace calped::calibrate_tool {

bool readTextFile(const std::string &path, std::string &out, std::string &error)
{
	std::FILE *f = std::fopen(path.c_str(), "rb");
	if (!f) {
		error = "cannot open " + path + ": " + std::strerror(errno);
		return false;
	}
	std::string text;
	char buffer[1 << 14];
	size_t n;
	while ((n = std::fread(buffer, 1, sizeof(buffer), f)) > 0)
		text.append(buffer, n);
	const bool failed = std::ferror(f) != 0;
	std::fclose(f);
	if (failed) {
		error = "cannot read " + path;
		return false;
	}
	out.swap(text);
	return true;
}

bool writeTextFile(const std::string &path, const std::string &text, std::string &error)
{
	std::FILE *f = std::fopen(path.c_str(), "wb");
	if (!f) {
		error = "cannot create " + path + ": " + std::strerror(errno);
		return false;
	}
	const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
	if (std::fclose(f) != 0 || !ok) {
		error = "cannot write " + path;
		return false;
	}
	return true;
}

} // namespace calped::calibrate_tool
