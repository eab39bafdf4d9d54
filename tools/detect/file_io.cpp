// SPDX-License-Identifier: BSD-2-Clause
#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

namespace calped::detect_tool {

namespace {
struct FileCloser {
	void operator()(FILE *f) const { std::fclose(f); }
};
} // namespace

bool readFile(const std::string &path, std::vector<uint8_t> &out, std::string &error,
	      const std::string &what)
{
	out.clear();
	std::error_code ec;
	if (std::filesystem::is_directory(path, ec)) {
		error = "cannot read " + what + path + ": is a directory";
		return false;
	}
	std::unique_ptr<FILE, FileCloser> f(std::fopen(path.c_str(), "rb"));
	if (!f) {
		error = "cannot read " + what + path + ": " + std::strerror(errno);
		return false;
	}
	// Read in chunks rather than trusting a size from seeking (works for pipes too).
	uint8_t chunk[1 << 16];
	for (;;) {
		size_t n = std::fread(chunk, 1, sizeof(chunk), f.get());
		out.insert(out.end(), chunk, chunk + n);
		if (n < sizeof(chunk))
			break;
	}
	if (std::ferror(f.get())) {
		error = "cannot read " + what + path + ": " + std::strerror(errno);
		out.clear();
		return false;
	}
	return true;
}

bool makeDirectories(const std::string &path, std::string &error)
{
	std::error_code ec;
	std::filesystem::create_directories(path, ec);
	if (ec) {
		error = "cannot create folder " + path + ": " + ec.message();
		return false;
	}
	if (!std::filesystem::is_directory(path, ec)) {
		error = "cannot create folder " + path + ": a file of that name exists";
		return false;
	}
	return true;
}

} // namespace calped::detect_tool
