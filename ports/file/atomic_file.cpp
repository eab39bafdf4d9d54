// SPDX-License-Identifier: BSD-2-Clause
#include "atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace calped {
namespace ports {

AtomicFile::~AtomicFile()
{
	discard();
}

bool AtomicFile::open(const std::string &path, std::string &error)
{
	discard();
	struct stat st;
	if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
		error = "cannot write " + path + ": " +
			(S_ISDIR(st.st_mode) ? "is a folder" : "exists and is not a regular file") +
			" (not replaced)";
		return false;
	}
	static std::atomic<unsigned> counter{ 0 };
	temp_ = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
	const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
	if (fd < 0 || !(file_ = ::fdopen(fd, "w"))) {
		error = "cannot write " + path + ": " + std::strerror(errno);
		if (fd >= 0) {
			::close(fd);
			::unlink(temp_.c_str());
		}
		temp_.clear();
		return false;
	}
	path_ = path;
	return true;
}

bool AtomicFile::commit(std::string &error)
{
	if (!file_)
		return true;
	errno = 0;
	bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
	int why = errno;
	ok = std::fclose(file_) == 0 && ok;
	if (!why)
		why = errno;
	file_ = nullptr;
	if (ok && ::rename(temp_.c_str(), path_.c_str()) != 0) {
		ok = false;
		why = errno;
	}
	if (!ok) {
		error = "cannot write " + path_ + ": " + (why ? std::strerror(why) : "write error");
		::unlink(temp_.c_str());
	}
	temp_.clear();
	return ok;
}

void AtomicFile::discard()
{
	if (file_)
		std::fclose(file_);
	file_ = nullptr;
	if (!temp_.empty())
		::unlink(temp_.c_str());
	temp_.clear();
}

} // namespace ports
} // namespace calped
