// SPDX-License-Identifier: BSD-2-Clause
// Command-line options shared by the live examples (calped-aravis, calped-play,
// calped-libcamera): the detector flags (tools/common/detector_options.h), outputs and when
// to stop. Each example puts its source's own options in the same table.
#pragma once

#include <string>
#include <vector>

#include "args.h"
#include "detector_options.h"
#include "mqtt_options.h"
#include "program.h"

namespace calped {
namespace live {

struct LiveOptions {
	apps::DetectorOptions detector; // --model, --calib, --method, --resize, ...
	std::string overlayDir;    // --overlay DIR
	long overlayEvery = 1;     // --overlay-every K
	long frames = 0;           // --frames N: stop after N processed frames (0: until stopped)
	double statsEvery = 5.0;   // --stats-every S: seconds between stats lines on stderr
	long timeoutMs = 2000;     // --timeout MS: wait per frame before counting a timeout
	double frameTimeoutS = 30; // --frame-timeout S: give up after S s without a complete frame (0: never)
	bool quiet = false;        // --quiet: no stats lines
	apps::MqttOptions mqtt;    // --mqtt URL, --mqtt-queue N, --camera-id ID
};

// The common options' table entries (with a heading), for the example's table.
std::vector<apps::OptionSpec> liveOptionTable();

// Consumes one of the common options and returns true (`error` set for a bad value);
// false lets the example take it.
bool takeLiveOption(const apps::ParsedOption &option, LiveOptions &out, std::string &error);

// Cross-option checks after every option was parsed (e.g. --model given).
bool checkLiveOptions(LiveOptions &options, std::string &error);

// The example's command line: its own options (`own`, first in --help) and the common
// ones, which fill `options`; the example's own are left in `rest.options`. -1 to go on,
// else the exit status (apps::parseCommandLine).
int parseLiveCommandLine(const apps::ProgramInfo &program, const std::vector<apps::OptionSpec> &own,
			 int argc, const char *const *argv, LiveOptions &options, apps::ParsedArgs &rest);

// The end of --help: output and exit status.
const char *liveEpilogue();

} // namespace live
} // namespace calped
