// SPDX-License-Identifier: BSD-2-Clause
// Is a GigE Vision camera still there? One READREG of the Version bootstrap register from a
// socket of our own, with a short timeout: Aravis's control channel retries for seconds
// (and queues behind its heartbeat), too slow to tell a dead camera from a quiet one.
#pragma once

namespace calped {
namespace ports {

enum class GvcpProbe {
	Answers, // an acknowledge came back
	Refused, // the host said nothing listens on GVCP's port (the camera process is gone)
	Silent,  // no answer within the timeout (unplugged, powered off, or too busy)
};

// `ipv4` is the camera's dotted address; GVCP's port 3956.
GvcpProbe probeGvcp(const char *ipv4, int timeoutMs);

} // namespace ports
} // namespace calped
