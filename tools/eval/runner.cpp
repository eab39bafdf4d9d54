// SPDX-License-Identifier: BSD-2-Clause
#include "runner.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>

#include "external_tools.h"
#include "stop_signal.h"
#include "overlay_frames.h"

namespace calped::eval_tool {

namespace {

static_assert(std::is_trivially_copyable<RunCounters>::value, "RunCounters travels as bytes");

// Child -> harness: one status byte, then either an error message or the counters,
// the frame count and each frame's detections. Same machine, so native byte order.
constexpr unsigned char kFailed = 0, kDone = 1;

template <typename T>
void put(std::vector<unsigned char> &out, const T &v)
{
	const unsigned char *p = reinterpret_cast<const unsigned char *>(&v);
	out.insert(out.end(), p, p + sizeof(T));
}

template <typename T>
bool get(const std::vector<unsigned char> &in, size_t &pos, T &v)
{
	if (in.size() - pos < sizeof(T))
		return false;
	std::memcpy(&v, in.data() + pos, sizeof(T));
	pos += sizeof(T);
	return true;
}

std::vector<unsigned char> encodeError(const std::string &message)
{
	std::vector<unsigned char> out;
	put(out, kFailed);
	out.insert(out.end(), message.begin(), message.end());
	return out;
}

bool writeAll(int fd, const std::vector<unsigned char> &bytes)
{
	size_t done = 0;
	while (done < bytes.size()) {
		const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0)
			return false;
		done += static_cast<size_t>(n);
	}
	return true;
}

// The child: run, report, and leave without the harness's exit handlers.
[[noreturn]] void childMain(const RunSpec &spec, const RunSettings &settings, int fd)
{
	RunResult run;
	std::string error;
	std::vector<unsigned char> bytes;
	if (runMethod(*spec.method, spec.resize, settings, run, error)) {
		struct rusage ru;
		if (getrusage(RUSAGE_SELF, &ru) == 0)
			run.counters.peakRssKib = ru.ru_maxrss; // KiB on Linux
		bytes = encodeRun(run);
	} else {
		bytes = encodeError(error);
	}
	const bool ok = writeAll(fd, bytes);
	close(fd);
	std::fflush(nullptr);
	_exit(ok ? 0 : 3);
}

struct Child {
	pid_t pid = -1;
	int fd = -1;
	size_t spec = 0;
	std::vector<unsigned char> bytes;
};

void stopChildren(std::vector<Child> &running)
{
	for (Child &c : running) {
		kill(c.pid, SIGTERM);
		close(c.fd);
		int status;
		waitpid(c.pid, &status, 0);
	}
	running.clear();
}

} // namespace

std::vector<unsigned char> encodeRun(const RunResult &run)
{
	std::vector<unsigned char> out;
	put(out, kDone);
	put(out, run.counters);
	put(out, static_cast<int64_t>(run.frames));
	put(out, static_cast<uint64_t>(run.detections.size()));
	for (const std::vector<ScoredBox> &frame : run.detections) {
		put(out, static_cast<uint32_t>(frame.size()));
		for (const ScoredBox &d : frame) {
			put(out, d.box.x);
			put(out, d.box.y);
			put(out, d.box.w);
			put(out, d.box.h);
			put(out, d.score);
		}
	}
	return out;
}

bool decodeRun(const std::vector<unsigned char> &in, RunResult &run, std::string &error)
{
	size_t pos = 0;
	unsigned char status;
	if (!get(in, pos, status)) {
		error = "the run ended without a result";
		return false;
	}
	if (status == kFailed) {
		error.assign(in.begin() + 1, in.end());
		return false;
	}
	int64_t frames;
	uint64_t n;
	if (status != kDone || !get(in, pos, run.counters) || !get(in, pos, frames) ||
	    !get(in, pos, n) || n > in.size()) {
		error = "the run sent a malformed result";
		return false;
	}
	run.hasCounters = true;
	run.frames = static_cast<long>(frames);
	run.detections.assign(static_cast<size_t>(n), {});
	for (std::vector<ScoredBox> &frame : run.detections) {
		uint32_t count;
		if (!get(in, pos, count) || count > in.size()) {
			error = "the run sent a malformed result";
			return false;
		}
		frame.resize(count);
		for (ScoredBox &d : frame) {
			if (!get(in, pos, d.box.x) || !get(in, pos, d.box.y) || !get(in, pos, d.box.w) ||
			    !get(in, pos, d.box.h) || !get(in, pos, d.score)) {
				error = "the run sent a truncated result";
				return false;
			}
		}
	}
	return true;
}

bool runAll(const std::vector<RunSpec> &specs, const RunSettings &settings, int jobs,
	    std::vector<RunResult> &results, std::string &error)
{
	results.assign(specs.size(), RunResult());
	error.clear();
	std::vector<Child> running;
	size_t next = 0;
	if (jobs < 1)
		jobs = 1;
	// Largest resize (the longest run) first, so parallel runs finish close together.
	std::vector<size_t> order(specs.size());
	for (size_t i = 0; i < order.size(); i++)
		order[i] = i;
	std::stable_sort(order.begin(), order.end(),
			 [&](size_t a, size_t b) { return specs[a].resize > specs[b].resize; });
	while (next < specs.size() || !running.empty()) {
		if (apps::stopRequested()) {
			// Each run finishes its frame and closes its outputs on the SIGTERM it gets.
			stopChildren(running);
			error = "stopped by a signal";
			return false;
		}
		while (next < specs.size() && static_cast<int>(running.size()) < jobs) {
			int fds[2];
			if (pipe2(fds, O_CLOEXEC) != 0) {
				error = std::string("cannot create a pipe: ") + std::strerror(errno);
				stopChildren(running);
				return false;
			}
			std::fflush(nullptr); // else the child would print our buffered output again
			const pid_t pid = fork();
			if (pid < 0) {
				error = std::string("cannot start a run: ") + std::strerror(errno);
				close(fds[0]);
				close(fds[1]);
				stopChildren(running);
				return false;
			}
			if (pid == 0) {
				close(fds[0]);
				for (const Child &c : running)
					close(c.fd);
				childMain(specs[order[next]], settings, fds[1]);
			}
			close(fds[1]);
			Child c;
			c.pid = pid;
			c.fd = fds[0];
			c.spec = order[next++];
			running.push_back(std::move(c));
		}

		std::vector<pollfd> fds;
		for (const Child &c : running)
			fds.push_back({ c.fd, POLLIN, 0 });
		if (poll(fds.data(), fds.size(), -1) < 0) {
			if (errno == EINTR)
				continue;
			error = std::string("cannot wait for the runs: ") + std::strerror(errno);
			stopChildren(running);
			return false;
		}
		for (size_t i = running.size(); i-- > 0;) {
			if (!fds[i].revents)
				continue;
			Child &c = running[i];
			unsigned char buf[1 << 16];
			const ssize_t n = read(c.fd, buf, sizeof(buf));
			if (n < 0 && errno == EINTR)
				continue;
			if (n > 0) {
				c.bytes.insert(c.bytes.end(), buf, buf + n);
				continue;
			}
			// End of the child's output: collect it and its exit status.
			close(c.fd);
			int status = 0;
			waitpid(c.pid, &status, 0);
			const RunSpec &spec = specs[c.spec];
			const std::string stem = runStem(spec.method->name, spec.resize);
			RunResult &r = results[c.spec];
			std::string why;
			const bool decoded = decodeRun(c.bytes, r, why);
			running.erase(running.begin() + static_cast<long>(i));
			// A failed run reports its error and exits 0; anything else is a crash.
			if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
				error = stem + ": the run's process ended abnormally (" +
					describeExitStatus(status) + ")";
			else if (!decoded)
				error = stem + ": " + why;
			if (!error.empty()) {
				stopChildren(running);
				return false;
			}
			r.method = spec.method->name;
			r.resize = spec.resize;
		}
	}
	return true;
}

} // namespace calped::eval_tool
