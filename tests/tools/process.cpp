// SPDX-License-Identifier: BSD-2-Clause
#include "process.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

ProcessResult runProcess(const std::string &program, const std::vector<std::string> &args,
			 const std::string &scratchDir)
{
	ProcessResult r;
	const std::string outPath = scratchDir + "/.stdout";
	const std::string errPath = scratchDir + "/.stderr";

	std::vector<char *> argv;
	argv.push_back(const_cast<char *>(program.c_str()));
	for (const std::string &a : args)
		argv.push_back(const_cast<char *>(a.c_str()));
	argv.push_back(nullptr);

	pid_t pid = fork();
	if (pid < 0) {
		r.err = "fork failed";
		return r;
	}
	if (pid == 0) {
		int in = open("/dev/null", O_RDONLY);
		int out = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
		int err = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
		if (in < 0 || out < 0 || err < 0)
			_exit(127);
		dup2(in, 0);
		dup2(out, 1);
		dup2(err, 2);
		execv(program.c_str(), argv.data());
		_exit(127);
	}

	int status = 0;
	pid_t waited;
	do {
		waited = waitpid(pid, &status, 0);
	} while (waited < 0 && errno == EINTR);
	if (waited < 0) {
		r.err = "waitpid failed";
		return r;
	}
	if (WIFEXITED(status)) {
		r.exited = true;
		r.exitCode = WEXITSTATUS(status);
	} else if (WIFSIGNALED(status)) {
		r.signal = WTERMSIG(status);
	}
	r.out = readTextFile(outPath);
	r.err = readTextFile(errPath);
	unlink(outPath.c_str());
	unlink(errPath.c_str());
	return r;
}

} // namespace calped::test
