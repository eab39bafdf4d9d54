// SPDX-License-Identifier: BSD-2-Clause
// Sizes the receive buffer of Aravis's GigE Vision stream socket before acquisition starts.
//
// Why: Aravis 0.8 applies its "socket-buffer" setting (fixed or auto) only when its stream
// thread handles the first packet of a frame. Until then the socket has the system default
// (net.core.rmem_default, 208 KiB), which holds about 92 packets of 1400 bytes on loopback:
// when the thread starts late (a busy CPU), the first frame overflows it and arrives with
// hundreds of packets missing. Linux only: finds the socket by its local port.
#pragma once

#include <cstdint>

namespace calped {
namespace ports {

// Sets SO_RCVBUF (SO_RCVBUFFORCE when permitted, which may exceed net.core.rmem_max) of
// this process's UDP socket bound to `localPort`. False when no such socket was found or
// the kernel refused.
bool presizeUdpSocket(uint16_t localPort, int bytes);

} // namespace ports
} // namespace calped
