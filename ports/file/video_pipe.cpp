// SPDX-License-Identifier: BSD-2-Clause
#include "video_pipe.h"

#include "probe_output.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

namespace calped {
namespace ports {

namespace {

struct Child {
	pid_t pid = -1;
	int out = -1;
	int err = -1;
};

// ffprobe reads a header: a minute is a hung child (a FIFO named like a video), not a slow one.
constexpr int kProbeTimeoutMs = 60000;

long long monotonicMs()
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return static_cast<long long>(t.tv_sec) * 1000 + t.tv_nsec / 1000000;
}

// Runs argv[0] from PATH with stdout and stderr on pipes. errno-style code on failure.
int spawnWithPipes(const char *const argv[], Child &child)
{
	int out[2], err[2];
	if (pipe2(out, O_CLOEXEC) != 0)
		return errno;
	if (pipe2(err, O_CLOEXEC) != 0) {
		const int e = errno;
		::close(out[0]);
		::close(out[1]);
		return e;
	}
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_adddup2(&actions, out[1], 1);
	posix_spawn_file_actions_adddup2(&actions, err[1], 2);
	posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
	pid_t pid = -1;
	const int rc = posix_spawnp(&pid, argv[0], &actions, nullptr,
				    const_cast<char *const *>(argv), environ);
	posix_spawn_file_actions_destroy(&actions);
	::close(out[1]);
	::close(err[1]);
	if (rc != 0) {
		::close(out[0]);
		::close(err[0]);
		return rc;
	}
	child.pid = pid;
	child.out = out[0];
	child.err = err[0];
	return 0;
}

// What a child wrote on one pipe: its first bytes (the rest is read and dropped).
struct Captured {
	char text[256] = {};
	size_t size = 0;
	bool more = false; // it wrote more than fits
};

void keep(Captured &c, const char *bytes, size_t n)
{
	const size_t room = sizeof(c.text) - 1 - c.size;
	if (n > room)
		c.more = true;
	n = std::min(n, room);
	std::memcpy(c.text + c.size, bytes, n);
	c.size += n;
	c.text[c.size] = '\0';
}

// Reads the child's stdout and stderr together until both end, so that a child writing
// much on one while we wait on the other never blocks on a full pipe. False when neither
// ended within timeoutMs (the child is then killed).
bool drainBoth(Child &child, Captured &out, Captured &err, int timeoutMs)
{
	int fds[2] = { child.out, child.err };
	Captured *into[2] = { &out, &err };
	const long long deadline = monotonicMs() + timeoutMs;
	while (fds[0] >= 0 || fds[1] >= 0) {
		struct pollfd p[2] = { { fds[0], POLLIN, 0 }, { fds[1], POLLIN, 0 } };
		const long long left = deadline - monotonicMs();
		if (left <= 0) {
			::kill(child.pid, SIGKILL);
			return false;
		}
		const int ready = poll(p, 2, static_cast<int>(std::min(left, 1000LL)));
		if (ready < 0 && errno != EINTR)
			return false;
		for (int k = 0; k < 2; k++) {
			if (fds[k] < 0 || !(p[k].revents & (POLLIN | POLLHUP | POLLERR)))
				continue;
			char chunk[4096];
			const ssize_t r = ::read(fds[k], chunk, sizeof(chunk));
			if (r < 0 && (errno == EINTR || errno == EAGAIN))
				continue;
			if (r <= 0)
				fds[k] = -1; // its end (or an error): that pipe is done
			else
				keep(*into[k], chunk, static_cast<size_t>(r));
		}
	}
	return true;
}

// The first line of what the child wrote on stderr, trailing space trimmed.
const char *oneLine(Captured &c)
{
	size_t n = c.size;
	while (n > 0 && std::isspace(static_cast<unsigned char>(c.text[n - 1])))
		n--;
	c.text[n] = '\0';
	for (size_t i = 0; i < n; i++)
		if (static_cast<unsigned char>(c.text[i]) < 0x20 || c.text[i] == 0x7f)
			c.text[i] = ' ';
	return c.text;
}

int reap(pid_t pid)
{
	int status = 0;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
	}
	return status;
}

const char *missingToolHint(int error)
{
	return error == ENOENT ? " (not found on PATH; install ffmpeg)" : "";
}

} // namespace

bool isVideoFileName(const std::string &path)
{
	const size_t dot = path.rfind('.');
	if (dot == std::string::npos)
		return false;
	std::string ext = path.substr(dot + 1);
	for (char &c : ext)
		c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	for (const char *v : { "avi", "mp4", "mkv", "mov", "webm", "mpg", "mpeg", "m4v", "y4m" })
		if (ext == v)
			return true;
	return false;
}

Status probeVideo(const std::string &path, int &width, int &height)
{
	if (access(path.c_str(), R_OK) != 0)
		return Status::error(ErrorCode::IoError, "cannot read %s: %s", path.c_str(),
				     std::strerror(errno));
	const char *argv[] = { "ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
			       "stream=width,height", "-of", "csv=p=0:s=x", path.c_str(), nullptr };
	Child child;
	const int rc = spawnWithPipes(argv, child);
	if (rc != 0)
		return Status::error(ErrorCode::IoError, "cannot run ffprobe for %s: %s%s",
				     path.c_str(), std::strerror(rc), missingToolHint(rc));
	Captured out, err;
	const bool ended = drainBoth(child, out, err, kProbeTimeoutMs);
	::close(child.out);
	::close(child.err);
	const int status = reap(child.pid);
	if (!ended)
		return Status::error(ErrorCode::IoError, "ffprobe did not finish on %s within %d s",
				     path.c_str(), kProbeTimeoutMs / 1000);
	// Where posix_spawnp cannot report a failed exec (qemu-user runs the child as a plain
	// fork), the child exits 127 without a word: the program is not there.
	if (WIFEXITED(status) && WEXITSTATUS(status) == 127 && out.size == 0 && err.size == 0)
		return Status::error(ErrorCode::IoError, "cannot run ffprobe for %s: %s%s",
				     path.c_str(), std::strerror(ENOENT), missingToolHint(ENOENT));
	int w = 0, h = 0;
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || out.more ||
	    !parseProbedSize(out.text, out.size, w, h))
		return Status::error(ErrorCode::IoError, "cannot decode %s as video: %s", path.c_str(),
				     err.size ? oneLine(err) : "no video stream of a size in 1..16384");
	width = w;
	height = h;
	return Status::success();
}

Status VideoPipe::open(const std::string &path, int width, int height)
{
	close();
	path_ = path;
	frameBytes_ = static_cast<size_t>(width) * height * 3;
	char size[32];
	std::snprintf(size, sizeof(size), "%dx%d", width, height);
	// -s pins the output size: a stream that changes size mid-file is scaled, never
	// allowed to overrun the fixed buffer.
	const char *argv[] = { "ffmpeg", "-nostdin", "-loglevel", "error", "-i", path.c_str(), "-f",
			       "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-", nullptr };
	Child child;
	const int rc = spawnWithPipes(argv, child);
	if (rc != 0)
		return Status::error(ErrorCode::IoError, "cannot run ffmpeg for %s: %s%s", path.c_str(),
				     std::strerror(rc), missingToolHint(rc));
	pid_ = child.pid;
	dataFd_ = child.out;
	errorFd_ = child.err;
	got_ = 0;
	errorLength_ = 0;
	errorTail_[0] = '\0';
	return Status::success();
}

Status VideoPipe::read(uint8_t *pixels, int timeoutMs)
{
	if (dataFd_ < 0)
		return Status::error(ErrorCode::EndOfStream, "%s: no more frames", path_.c_str());
	while (got_ < frameBytes_) {
		struct pollfd fds[2] = { { dataFd_, POLLIN, 0 }, { errorFd_, POLLIN, 0 } };
		const int ready = poll(fds, errorFd_ >= 0 ? 2 : 1, timeoutMs);
		if (ready < 0 && errno != EINTR)
			return Status::error(ErrorCode::IoError, "waiting for frames of %s from ffmpeg: %s",
					     path_.c_str(), std::strerror(errno));
		if (ready <= 0)
			return Status::error(ErrorCode::Timeout, "%s: no frame data within %d ms",
					     path_.c_str(), timeoutMs);
		if (errorFd_ >= 0 && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) && !drainErrors()) {
			::close(errorFd_);
			errorFd_ = -1;
		}
		// At -loglevel error ffmpeg says nothing about a sound file; a line means damaged
		// data, and the frames it drops would silently renumber the rest.
		if (std::memchr(errorTail_, '\n', errorLength_)) {
			got_ = 0;
			return failed("ffmpeg reported an error decoding");
		}
		if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR)))
			continue;
		const ssize_t r = ::read(dataFd_, pixels + got_, frameBytes_ - got_);
		if (r < 0 && errno == EINTR)
			return Status::error(ErrorCode::Timeout, "%s: interrupted", path_.c_str());
		if (r < 0)
			return Status::error(ErrorCode::IoError, "reading frames of %s from ffmpeg: %s",
					     path_.c_str(), std::strerror(errno));
		if (r == 0)
			break;
		got_ += static_cast<size_t>(r);
	}
	const size_t got = got_;
	got_ = 0;
	if (got == frameBytes_)
		return Status::success();
	const Status end = finish();
	if (!end.ok())
		return end;
	if (got != 0)
		return Status::error(ErrorCode::IoError, "%s: ffmpeg ended inside a frame (%zu of %zu bytes)",
				     path_.c_str(), got, frameBytes_);
	return Status::error(ErrorCode::EndOfStream, "%s: no more frames", path_.c_str());
}

bool VideoPipe::drainErrors()
{
	char chunk[4096];
	const ssize_t r = ::read(errorFd_, chunk, sizeof(chunk));
	if (r < 0)
		return errno == EINTR || errno == EAGAIN;
	if (r == 0)
		return false;
	// Keep the last sizeof(errorTail_) - 1 bytes: the latest message is the one that explains.
	const size_t cap = sizeof(errorTail_) - 1;
	size_t n = static_cast<size_t>(r);
	const char *from = chunk;
	if (n >= cap) {
		from += n - cap;
		n = cap;
		errorLength_ = 0;
	} else if (errorLength_ + n > cap) {
		const size_t drop = errorLength_ + n - cap;
		std::memmove(errorTail_, errorTail_ + drop, errorLength_ - drop);
		errorLength_ -= drop;
	}
	std::memcpy(errorTail_ + errorLength_, from, n);
	errorLength_ += n;
	errorTail_[errorLength_] = '\0';
	return true;
}

Status VideoPipe::finish()
{
	while (errorFd_ >= 0 && drainErrors()) {
	}
	::close(dataFd_);
	if (errorFd_ >= 0)
		::close(errorFd_);
	dataFd_ = errorFd_ = -1;
	const int status = reap(pid_);
	pid_ = -1;
	if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && errorLength_ == 0)
		return Status::success();
	return Status::error(ErrorCode::IoError, "ffmpeg failed on %s: %s", path_.c_str(),
			     firstErrorLine().c_str());
}

Status VideoPipe::failed(const char *what)
{
	const std::string line = firstErrorLine();
	close();
	return Status::error(ErrorCode::IoError, "%s %s: %s", what, path_.c_str(), line.c_str());
}

std::string VideoPipe::firstErrorLine() const
{
	// One line of 160 bytes at most, control bytes as spaces: a log line, not a dump.
	size_t n = 0;
	while (n < errorLength_ && n < 160 && errorTail_[n] != '\n')
		n++;
	std::string line(errorTail_, n);
	for (char &c : line)
		if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
			c = ' ';
	while (!line.empty() && line.back() == ' ')
		line.pop_back();
	return line.empty() ? "no message" : line;
}

void VideoPipe::close()
{
	if (pid_ > 0)
		kill(pid_, SIGTERM);
	if (dataFd_ >= 0)
		::close(dataFd_);
	if (errorFd_ >= 0)
		::close(errorFd_);
	if (pid_ > 0)
		reap(pid_);
	pid_ = -1;
	dataFd_ = errorFd_ = -1;
}

} // namespace ports
} // namespace calped
