// SPDX-License-Identifier: BSD-2-Clause
#include "socket_presize.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <sys/socket.h>
#include <unistd.h>

namespace calped {
namespace ports {

namespace {

// The inode of the UDP socket bound to `port`, from a /proc/net/udp-style table.
unsigned long socketInode(const char *table, uint16_t port)
{
	FILE *f = std::fopen(table, "r");
	if (!f)
		return 0;
	char line[512];
	unsigned long inode = 0;
	if (!std::fgets(line, sizeof(line), f)) { // header
		std::fclose(f);
		return 0;
	}
	while (!inode && std::fgets(line, sizeof(line), f)) {
		char local[64];
		unsigned long node = 0;
		// sl local_address rem_address st tx:rx tr:when retrnsmt uid timeout inode
		if (std::sscanf(line, " %*s %63s %*s %*s %*s %*s %*s %*s %*s %lu", local, &node) != 2)
			continue;
		const char *colon = std::strrchr(local, ':');
		if (colon && std::strtoul(colon + 1, nullptr, 16) == port)
			inode = node;
	}
	std::fclose(f);
	return inode;
}

} // namespace

bool presizeUdpSocket(uint16_t localPort, int bytes)
{
	unsigned long inode = socketInode("/proc/self/net/udp", localPort);
	if (!inode)
		inode = socketInode("/proc/self/net/udp6", localPort);
	if (!inode)
		return false;
	char wanted[64];
	std::snprintf(wanted, sizeof(wanted), "socket:[%lu]", inode);
	DIR *dir = opendir("/proc/self/fd");
	if (!dir)
		return false;
	bool done = false;
	while (const dirent *e = readdir(dir)) {
		char path[300], target[64];
		std::snprintf(path, sizeof(path), "/proc/self/fd/%s", e->d_name);
		const ssize_t n = readlink(path, target, sizeof(target) - 1);
		if (n <= 0)
			continue;
		target[n] = '\0';
		if (std::strcmp(target, wanted) != 0)
			continue;
		const int fd = std::atoi(e->d_name);
		done = setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &bytes, sizeof(bytes)) == 0 ||
		       setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof(bytes)) == 0;
		break;
	}
	closedir(dir);
	return done;
}

} // namespace ports
} // namespace calped
