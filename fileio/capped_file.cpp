// SPDX-License-Identifier: BSD-2-Clause
#include "capped_file.h"

#include "excerpt.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace calped {
namespace files {

bool readFileBytes(const std::string &path, std::vector<uint8_t> &out, std::string &error,
		   const std::string &what, size_t maxBytes)
{
	out.clear();
	// Messages name the file escaped (a name may hold control bytes or invalid UTF-8).
	auto named = [&path] { return excerpt(path, kExcerptPathBytes); };
	// stat(), not std::filesystem: a path object would allocate on every frame. Only a
	// regular file: a FIFO would block for ever, a device (/dev/zero) never ends.
	struct stat st;
	if (::stat(path.c_str(), &st) != 0) {
		error = "cannot read " + what + named() + ": " + std::strerror(errno);
		return false;
	}
	if (!S_ISREG(st.st_mode)) {
		error = "cannot read " + what + named() + ": " +
			(S_ISDIR(st.st_mode) ? "is a directory" : S_ISFIFO(st.st_mode) ? "is a FIFO, not a regular file"
				: "is a device or socket, not a regular file");
		return false;
	}
	if (static_cast<unsigned long long>(st.st_size) > maxBytes) {
		error = "cannot read " + what + named() + ": " + std::to_string(st.st_size) + " bytes, over the " +
			std::to_string(maxBytes) + "-byte limit for this kind of file (docs/errors.md)";
		return false;
	}
	// O_NONBLOCK: if the path was swapped for a FIFO since stat(), open() must not wait.
	const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0) {
		error = "cannot read " + what + named() + ": " + std::strerror(errno);
		return false;
	}
	struct stat opened;
	if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
		::close(fd);
		error = "cannot read " + what + named() + ": not a regular file";
		return false;
	}
	// Up to the cap and one byte more: a file that grew past it is refused, not cut.
	out.resize(std::min<size_t>(static_cast<size_t>(opened.st_size), maxBytes) + 1);
	size_t got = 0;
	for (;;) {
		if (got == out.size()) {
			if (got > maxBytes)
				break;
			out.resize(std::min(out.size() * 2, maxBytes + 1));
		}
		const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0) {
			const int e = errno;
			::close(fd);
			out.clear();
			error = "cannot read " + what + named() + ": " + std::strerror(e);
			return false;
		}
		if (n == 0)
			break;
		got += static_cast<size_t>(n);
	}
	::close(fd);
	if (got > maxBytes) {
		out.clear();
		error = "cannot read " + what + named() + ": over the " + std::to_string(maxBytes) +
			"-byte limit for this kind of file (docs/errors.md)";
		return false;
	}
	out.resize(got);
	return true;
}

} // namespace files
} // namespace calped
