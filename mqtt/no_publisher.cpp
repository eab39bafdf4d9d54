// SPDX-License-Identifier: BSD-2-Clause
// Built instead of mosquitto_publisher.cpp where libmosquitto is absent (or -Dmqtt=disabled):
// the programs keep their --mqtt option and say at start why it cannot work.
#include "publisher.h"

namespace calped::mqtt {

bool mqttAvailable()
{
	return false;
}

bool Publisher::open(const PublisherOptions &options, std::unique_ptr<Publisher> &,
		     std::string &error)
{
	error = "cannot publish to " + options.url.hostPort() +
		": calped was built without MQTT (install libmosquitto-dev and reconfigure with -Dmqtt=enabled)";
	return false;
}

} // namespace calped::mqtt
