// SPDX-License-Identifier: BSD-2-Clause
#include "external_tools.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>

namespace calped::eval_tool {

std::string shellQuote(const std::string &text)
{
	std::string out = "'";
	for (char c : text) {
		if (c == '\'')
			out += "'\\''";
		else
			out += c;
	}
	return out + "'";
}

bool findExecutable(const std::string &name)
{
	const char *path = std::getenv("PATH");
	if (!path)
		return false;
	std::string dirs = path;
	size_t pos = 0;
	for (;;) {
		size_t colon = dirs.find(':', pos);
		std::string dir = dirs.substr(pos, colon == std::string::npos ? std::string::npos
									       : colon - pos);
		if (dir.empty())
			dir = ".";
		if (access((dir + "/" + name).c_str(), X_OK) == 0)
			return true;
		if (colon == std::string::npos)
			return false;
		pos = colon + 1;
	}
}

std::string describeExitStatus(int status)
{
	if (status == -1)
		return std::string("could not run it: ") + std::strerror(errno);
	if (WIFEXITED(status))
		return "exit status " + std::to_string(WEXITSTATUS(status));
	if (WIFSIGNALED(status))
		return "signal " + std::to_string(WTERMSIG(status));
	return "status " + std::to_string(status);
}

bool runCapture(const std::string &command, std::string &output, std::string &error)
{
	output.clear();
	std::fflush(nullptr); // the child must not repeat our buffered output
	FILE *p = popen(command.c_str(), "r");
	if (!p) {
		error = "cannot run " + command + ": " + std::strerror(errno);
		return false;
	}
	char buf[4096];
	size_t n;
	while ((n = std::fread(buf, 1, sizeof(buf), p)) > 0)
		output.append(buf, n);
	const int status = pclose(p);
	if (status != 0) {
		error = command + " failed (" + describeExitStatus(status) + ")";
		return false;
	}
	return true;
}

} // namespace calped::eval_tool
