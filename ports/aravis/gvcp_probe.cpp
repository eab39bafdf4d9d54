// SPDX-License-Identifier: BSD-2-Clause
#include "gvcp_probe.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstdint>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace calped {
namespace ports {

namespace {

constexpr uint16_t kGvcpPort = 3956;
constexpr uint8_t kGvcpKey = 0x42;
constexpr uint8_t kFlagAckRequired = 0x01;
constexpr uint16_t kReadRegCmd = 0x0080;
constexpr uint16_t kReadRegAck = 0x0081;
constexpr uint16_t kRequestId = kGvcpProbeRequestId;

uint16_t bigEndian16(const uint8_t *p)
{
	return static_cast<uint16_t>((p[0] << 8) | p[1]);
}

} // namespace

bool isProbeAnswer(const uint8_t *reply, size_t n)
{
	// Header: status, answer, payload length, ack id (big-endian), then the payload: for a
	// READREG_ACK the 4 bytes of each register read (one here).
	if (!reply || n < 8 || bigEndian16(reply + 2) != kReadRegAck ||
	    bigEndian16(reply + 6) != kRequestId)
		return false;
	const size_t length = bigEndian16(reply + 4);
	return length == 4 && n >= 8 + length;
}

GvcpProbe probeGvcp(const char *ipv4, int timeoutMs)
{
	sockaddr_in to{};
	to.sin_family = AF_INET;
	to.sin_port = htons(kGvcpPort);
	if (inet_pton(AF_INET, ipv4, &to.sin_addr) != 1)
		return GvcpProbe::Silent;
	const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (fd < 0)
		return GvcpProbe::Silent;
	// connect() makes the kernel report "port unreachable" as ECONNREFUSED.
	GvcpProbe result = GvcpProbe::Silent;
	if (connect(fd, reinterpret_cast<const sockaddr *>(&to), sizeof(to)) == 0) {
		// Header: key, flags, command, payload length, request id; then the register
		// address (0x0000, Version), all big-endian.
		const uint8_t cmd[12] = { kGvcpKey, kFlagAckRequired, kReadRegCmd >> 8, kReadRegCmd & 0xff,
					  0, 4, kRequestId >> 8, kRequestId & 0xff, 0, 0, 0, 0 };
		if (send(fd, cmd, sizeof(cmd), 0) == static_cast<ssize_t>(sizeof(cmd))) {
			pollfd p{ fd, POLLIN, 0 };
			int ready;
			while ((ready = poll(&p, 1, timeoutMs)) < 0 && errno == EINTR) {
			}
			if (ready > 0) {
				uint8_t ack[64];
				const ssize_t n = recv(fd, ack, sizeof(ack), 0);
				if (n < 0 && errno == ECONNREFUSED)
					result = GvcpProbe::Refused;
				else if (n > 0 && isProbeAnswer(ack, static_cast<size_t>(n)))
					result = GvcpProbe::Answers;
			}
		} else if (errno == ECONNREFUSED) {
			result = GvcpProbe::Refused;
		}
	}
	close(fd);
	return result;
}

} // namespace ports
} // namespace calped
