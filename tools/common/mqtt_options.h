// SPDX-License-Identifier: BSD-2-Clause
// The MQTT flags of calped-detect and the live programs (--mqtt URL, --mqtt-queue N,
// --camera-id ID; docs/cli.md, docs/mqtt.md), parsed like the detector flags, and the
// publisher they open.
#pragma once

#include <string>
#include <vector>

#include "args.h"
#include "frame_publisher.h"

namespace calped::apps {

struct MqttOptions {
	std::string url;      // --mqtt: empty means no publishing
	std::string cameraId; // --camera-id (default: the host name)
	long queue = 1000;    // --mqtt-queue: messages not yet acknowledged by the broker
};

// The flags' table entries, with a heading.
std::vector<OptionSpec> mqttOptionTable();

// Consumes one parsed option if it is an MQTT flag and returns true; `error` is then set
// when its value is bad (a bad URL is a usage error). False: not an MQTT flag.
bool takeMqttOption(const ParsedOption &option, MqttOptions &out, std::string &error);

// Cross-flag checks: --camera-id or --mqtt-queue without --mqtt.
bool checkMqttOptions(const MqttOptions &options, std::string &error);

// Connects when --mqtt was given (true and nothing opened otherwise); false with `error`
// naming the broker when it cannot be reached (a runtime error).
bool openMqtt(const MqttOptions &options, mqtt::FramePublisher &publisher, std::string &error);

// Closes the publisher (waiting for the broker's acknowledgements) and prints its summary
// on standard error as "PROGRAM: mqtt ...", unless `quiet`.
void closeMqtt(mqtt::FramePublisher &publisher, const char *program, bool quiet);

} // namespace calped::apps
