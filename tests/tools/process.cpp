// SPDX-License-Identifier: BSD-2-Clause
#include "process.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>
#include <fstream>
#include <sstream>

namespace calped::test {

std::string readTextFile(const std::string &path)
{
	std::ifstream in(path, std::ios::binary);
	std::ostringstream ss;
	ss << in.rdbuf();
	return ss.str();
}

std::vector<std::string> splitLines(const std::string &text)
{
	std::vector<std::string> lines;
	std::string line;
	std::istringstream in(text);
	while (std::getline(in, line))
		lines.push_back(line);
	return lines;
}

RunningProcess startProcess(const std::string &program, const std::vector<std::string> &args,
			    const std::string &scratchDir)
{
	RunningProcess p;
	p.outPath = scratchDir + "/.stdout";
	p.errPath = scratchDir + "/.stderr";

	std::vector<char *> argv;
	argv.push_back(const_cast<char *>(program.c_str()));
	for (const std::string &a : args)
		argv.push_back(const_cast<char *>(a.c_str()));
	argv.push_back(nullptr);

	const pid_t pid = fork();
	if (pid == 0) {
		int in = open("/dev/null", O_RDONLY);
		int out = open(p.outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
		int err = open(p.errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
		if (in < 0 || out < 0 || err < 0)
			_exit(127);
		dup2(in, 0);
		dup2(out, 1);
		dup2(err, 2);
		execv(program.c_str(), argv.data());
		_exit(127);
	}
	p.pid = pid;
	return p;
}

namespace {

ProcessResult collect(RunningProcess &p, int status)
{
	ProcessResult r;
	if (WIFEXITED(status)) {
		r.exited = true;
		r.exitCode = WEXITSTATUS(status);
	} else if (WIFSIGNALED(status)) {
		r.signal = WTERMSIG(status);
	}
	r.out = readTextFile(p.outPath);
	r.err = readTextFile(p.errPath);
	unlink(p.outPath.c_str());
	unlink(p.errPath.c_str());
	p.pid = -1;
	return r;
}

} // namespace

ProcessResult waitProcess(RunningProcess &p, double timeoutSeconds)
{
	if (p.pid < 0) {
		ProcessResult r;
		r.err = "fork failed";
		return r;
	}
	const auto deadline = std::chrono::steady_clock::now() +
			      std::chrono::duration_cast<std::chrono::steady_clock::duration>(
				      std::chrono::duration<double>(timeoutSeconds));
	int status = 0;
	for (;;) {
		const pid_t waited = waitpid(p.pid, &status, WNOHANG);
		if (waited == p.pid)
			return collect(p, status);
		if (waited < 0 && errno != EINTR) {
			ProcessResult r;
			r.err = "waitpid failed";
			return r;
		}
		if (std::chrono::steady_clock::now() >= deadline) {
			kill(p.pid, SIGKILL);
			while (waitpid(p.pid, &status, 0) < 0 && errno == EINTR) {
			}
			ProcessResult r = collect(p, status);
			r.hung = true;
			return r;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

ProcessResult runProcess(const std::string &program, const std::vector<std::string> &args,
			 const std::string &scratchDir)
{
	RunningProcess p = startProcess(program, args, scratchDir);
	if (p.pid < 0) {
		ProcessResult r;
		r.err = "fork failed";
		return r;
	}
	int status = 0;
	pid_t waited;
	do {
		waited = waitpid(p.pid, &status, 0);
	} while (waited < 0 && errno == EINTR);
	if (waited < 0) {
		ProcessResult r;
		r.err = "waitpid failed";
		return r;
	}
	return collect(p, status);
}

} // namespace calped::test
