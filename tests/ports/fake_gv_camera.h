// SPDX-License-Identifier: BSD-2-Clause
// Runs Debian's GigE Vision camera simulator (arv-fake-gv-camera-0.8, package
// aravis-tools) as a child process on a loopback address, for the Aravis port's tests.
#pragma once

#include <string>
#include <sys/types.h>

namespace calped {
namespace test {

// The simulator's path on PATH, or "" when aravis-tools is not installed.
std::string fakeGvCameraPath();

class FakeGvCamera
{
public:
	~FakeGvCamera() { kill(); }
	// Starts it on `address` (an address of a local interface, e.g. "127.0.0.1") dropping
	// `lostPerThousand` stream packets; waits until it listens on GVCP's port 3956.
	bool start(const std::string &address, int lostPerThousand, std::string &error);
	// SIGKILL, as a crashed or unplugged camera: no goodbye on the wire.
	void kill();
	bool running() const { return pid_ > 0; }

private:
	pid_t pid_ = -1;
};

} // namespace test
} // namespace calped
