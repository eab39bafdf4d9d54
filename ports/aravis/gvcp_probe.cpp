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
constexpr uint16_t kRequestId = 0x7e57;

} // namespace

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
				else if (n >= 8 && ((ack[2] << 8) | ack[3]) == kReadRegAck)
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
