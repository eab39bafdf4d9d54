// SPDX-License-Identifier: BSD-2-Clause
// Is a GigE Vision camera still there? One READREG of the Version bootstrap register from a
// socket of our own, with a short timeout: Aravis's control channel retries for seconds
// (and queues behind its heartbeat), too slow to tell a dead camera from a quiet one.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {
namespace ports {

enum class GvcpProbe {
	Answers, // an acknowledge came back
	Refused, // the host said nothing listens on GVCP's port (the camera process is gone)
	Silent,  // no answer within the timeout (unplugged, powered off, or too busy)
};

// The request id of the probe's READREG command.
constexpr uint16_t kGvcpProbeRequestId = 0x7e57;

// Whether `n` bytes received on the probe's socket are the camera's acknowledge of that
// READREG: a GVCP header (status, answer READREG_ACK, length, the request's id) and the
// register it read. Any status counts (a busy camera is there). Pure: fuzzed with the
// Aravis port's other checks (tests/fuzz/fuzz_aravis.cpp).
bool isProbeAnswer(const uint8_t *reply, size_t n);

// `ipv4` is the camera's dotted address; GVCP's port 3956.
GvcpProbe probeGvcp(const char *ipv4, int timeoutMs);

} // namespace ports
} // namespace calped
