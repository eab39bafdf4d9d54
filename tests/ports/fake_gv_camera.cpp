// SPDX-License-Identifier: BSD-2-Clause
#include "fake_gv_camera.h"

#include <arpa/inet.h>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char **environ;

namespace calped {
namespace test {

namespace {

const char *kBinary = "arv-fake-gv-camera-0.8";

// True when some socket is bound to address:3956 (GVCP), per /proc/net/udp.
bool listening(const std::string &address)
{
	in_addr a;
	if (inet_pton(AF_INET, address.c_str(), &a) != 1)
		return false;
	char wanted[32];
	std::snprintf(wanted, sizeof(wanted), "%08X:0F74", a.s_addr); // host order as the kernel prints it
	FILE *f = std::fopen("/proc/net/udp", "r");
	if (!f)
		return false;
	char line[512];
	bool found = false;
	while (!found && std::fgets(line, sizeof(line), f))
		found = std::strstr(line, wanted) != nullptr;
	std::fclose(f);
	return found;
}

} // namespace

std::string fakeGvCameraPath()
{
	const char *path = std::getenv("PATH");
	std::stringstream dirs(path ? path : "/usr/bin:/bin");
	std::string dir;
	while (std::getline(dirs, dir, ':')) {
		const std::string candidate = (dir.empty() ? "." : dir) + "/" + kBinary;
		if (access(candidate.c_str(), X_OK) == 0)
			return candidate;
	}
	return "";
}

bool FakeGvCamera::start(const std::string &address, int lostPerThousand, std::string &error)
{
	kill();
	const std::string binary = fakeGvCameraPath();
	if (binary.empty()) {
		error = "aravis-tools is not installed (no arv-fake-gv-camera-0.8 on PATH)";
		return false;
	}
	// GVCP's port is fixed: a simulator of another test run (another build tree or
	// worktree on this machine) would answer in place of ours, and our tests would fail
	// in ways that look like port bugs.
	if (listening(address)) {
		error = "another process already serves GVCP on " + address +
			":3956 (a simulator of another test run?): not starting a second one";
		return false;
	}
	const std::string lost = std::to_string(lostPerThousand);
	const char *argv[] = { binary.c_str(), "-i", address.c_str(), "-r", lost.c_str(), nullptr };
	posix_spawn_file_actions_t actions;
	posix_spawn_file_actions_init(&actions);
	posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
	posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
	const int rc = posix_spawn(&pid_, binary.c_str(), &actions, nullptr,
				   const_cast<char *const *>(argv), environ);
	posix_spawn_file_actions_destroy(&actions);
	if (rc != 0) {
		pid_ = -1;
		error = "cannot run " + binary + ": " + std::strerror(rc);
		return false;
	}
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
	while (std::chrono::steady_clock::now() < deadline) {
		if (listening(address))
			return true;
		int status = 0;
		if (waitpid(pid_, &status, WNOHANG) == pid_) {
			pid_ = -1;
			error = std::string(kBinary) + " exited at start (is " + address + " a local address, and is no other simulator running?)";
			return false;
		}
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
	kill();
	error = std::string(kBinary) + " did not listen on " + address + ":3956 within 5 s";
	return false;
}

void FakeGvCamera::kill()
{
	if (pid_ <= 0)
		return;
	::kill(pid_, SIGKILL);
	int status = 0;
	waitpid(pid_, &status, 0);
	pid_ = -1;
}

} // namespace test
} // namespace calped
