// SPDX-License-Identifier: BSD-2-Clause
#include "file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "atomic_file.h"
#include "image_io.h"

namespace calped::apps {

bool readFile(const std::string &path, std::vector<uint8_t> &out, std::string &error,
	      const std::string &what, size_t maxBytes)
{
	return ports::readFileBytes(path, out, error, what, maxBytes);
}

bool readTextFile(const std::string &path, std::string &out, std::string &error, size_t maxBytes)
{
	std::vector<uint8_t> bytes;
	if (!readFile(path, bytes, error, "", maxBytes))
		return false;
	out.assign(bytes.begin(), bytes.end());
	return true;
}

bool writeTextFile(const std::string &path, const std::string &text, std::string &error)
{
	ports::AtomicFile f; // renamed into place only when whole
	if (!f.open(path, error))
		return false;
	std::fwrite(text.data(), 1, text.size(), f.get());
	return f.commit(error);
}

bool isRegularFile(const std::string &path)
{
	std::error_code ec;
	return std::filesystem::is_regular_file(path, ec);
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

} // namespace calped::apps
