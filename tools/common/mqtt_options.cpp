// SPDX-License-Identifier: BSD-2-Clause
#include "mqtt_options.h"

#include <cstdio>

namespace calped::apps {

std::vector<OptionSpec> mqttOptionTable()
{
	return {
		{ nullptr, nullptr, "MQTT (docs/mqtt.md):" },
		{ "mqtt", "URL", "publish each frame's detections to mqtt://HOST[:PORT]/TOPIC\n"
				 "(QoS 1, one JSON message per frame)" },
		{ "mqtt-queue", "N", "hold at most N messages the broker has not acknowledged;\n"
				     "newer ones are dropped and counted (default 1000)" },
		{ "camera-id", "ID", "the camera's id in each message (default: the host name)" },
	};
}

bool takeMqttOption(const ParsedOption &o, MqttOptions &out, std::string &error)
{
	const std::string &n = o.name;
	if (n == "mqtt") {
		mqtt::MqttUrl url;
		std::string why;
		if (!mqtt::parseMqttUrl(o.value, url, why))
			error = o.flag + ": " + why;
		else
			out.url = o.value;
	} else if (n == "mqtt-queue") {
		wholeIn(o, 1, 1000000, out.queue, error);
	} else if (n == "camera-id") {
		nonEmpty(o, "a camera id", out.cameraId, error);
	} else {
		return false;
	}
	return true;
}

bool checkMqttOptions(const MqttOptions &options, std::string &error)
{
	if (options.url.empty() && (!options.cameraId.empty() || options.queue != MqttOptions().queue)) {
		error = "--camera-id and --mqtt-queue need --mqtt URL";
		return false;
	}
	return true;
}

bool openMqtt(const MqttOptions &options, mqtt::FramePublisher &publisher, std::string &error)
{
	if (options.url.empty())
		return true;
	mqtt::FramePublisherOptions p;
	p.url = options.url;
	p.cameraId = options.cameraId;
	p.queueCapacity = static_cast<size_t>(options.queue);
	return publisher.open(p, error);
}

void closeMqtt(mqtt::FramePublisher &publisher, const char *program, bool quiet)
{
	if (!publisher.isOpen())
		return;
	publisher.close();
	if (!quiet)
		std::fprintf(stderr, "%s: %s\n", program, publisher.summary().c_str());
}

} // namespace calped::apps
