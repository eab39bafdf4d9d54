// SPDX-License-Identifier: BSD-2-Clause
// SIGINT and SIGTERM as a request to stop, the same in every program: the handler only
// records the signal; the program finishes the frame it is on, writes complete lines and
// exits with 128 + the signal's number (130, 143), as a shell reports a killed program.
#pragma once

namespace calped::apps {

// Installs the handlers (without SA_RESTART, so a blocking read returns EINTR and the
// caller can look at stopRequested()) and ignores SIGPIPE (a closed output pipe becomes a
// reported write error, not a silent death). Safe to call more than once.
void installStopHandlers();

// True once SIGINT or SIGTERM arrived.
bool stopRequested();

// 128 + the signal that asked to stop; 0 when none did.
int stopExitCode();

} // namespace calped::apps
