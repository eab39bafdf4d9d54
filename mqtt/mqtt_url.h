// SPDX-License-Identifier: BSD-2-Clause
// The broker address the programs take: mqtt://HOST[:PORT]/TOPIC (docs/mqtt.md).
#pragma once

#include <string>

namespace calped::mqtt {

struct MqttUrl {
	std::string host;  // a name, an IPv4 address or an IPv6 address (written [::1] in the URL)
	int port = 1883;   // MQTT's registered port when the URL gives none
	std::string topic; // the rest of the path, without the first '/'

	std::string hostPort() const; // "HOST:PORT" ("[::1]:1883") for messages
};

// Strict: the scheme is mqtt://, the host is not empty, the port is 1..65535, the topic is
// not empty and is a topic one may publish to (no '+' or '#', no NUL, valid UTF-8, at most
// 65535 bytes); user names, passwords, queries and fragments are refused. False with a
// one-line `error` naming what is wrong.
bool parseMqttUrl(const std::string &text, MqttUrl &out, std::string &error);

} // namespace calped::mqtt
