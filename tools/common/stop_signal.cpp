// SPDX-License-Identifier: BSD-2-Clause
#include "stop_signal.h"

#include <csignal>
#include <cstring>

namespace calped::apps {

namespace {

volatile std::sig_atomic_t gStopSignal = 0;

void onStopSignal(int signal)
{
	gStopSignal = signal;
}

} // namespace

void installStopHandlers()
{
	struct sigaction sa;
	std::memset(&sa, 0, sizeof(sa));
	sa.sa_handler = onStopSignal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, nullptr);
	sigaction(SIGTERM, &sa, nullptr);
	std::signal(SIGPIPE, SIG_IGN);
}

bool stopRequested()
{
	return gStopSignal != 0;
}

int stopExitCode()
{
	return gStopSignal != 0 ? 128 + gStopSignal : 0;
}

} // namespace calped::apps
