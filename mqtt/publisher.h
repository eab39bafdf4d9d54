// SPDX-License-Identifier: BSD-2-Clause
// Publishes messages to one MQTT topic at QoS 1 over libmosquitto (docs/mqtt.md).
//
// open() connects and waits for the broker's CONNACK, a bounded time: an unreachable broker
// is an error at start, naming HOST:PORT. After that the broker may go away at any time:
// libmosquitto's network thread reconnects (1 s, doubling to 8 s) and resends every
// message that was not acknowledged (at least once: a subscriber may see a message twice).
// Messages sent but not yet acknowledged (PUBACK) form the queue; at most `queueCapacity`
// of them are held, and publish() refuses the newest one when the queue is full and counts
// it as dropped: the messages already queued stay in order and the loss is never silent.
// Threads: publish() and counts() from one thread; libmosquitto's callbacks update the
// counters from its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "mqtt_url.h"

namespace calped::mqtt {

struct PublisherOptions {
	MqttUrl url;
	size_t queueCapacity = 1000; // messages sent and not yet acknowledged
	int connectTimeoutMs = 5000; // open(): the broker's CONNACK within this time
	int flushTimeoutMs = 5000;   // close(): wait this long for the queue to be acknowledged
};

struct PublisherCounts {
	uint64_t offered = 0;      // publish() calls
	uint64_t sent = 0;         // taken into the queue (handed to libmosquitto)
	uint64_t acknowledged = 0; // PUBACK received
	uint64_t dropped = 0;      // refused: queue full (offered == sent + dropped)
	uint64_t reconnects = 0;   // connections after the first one
	// Sent and never acknowledged: 0 after a close() that flushed; they may or may not
	// have reached the broker.
	uint64_t unacknowledged() const { return sent > acknowledged ? sent - acknowledged : 0; }
};

// True where calped was built with libmosquitto (meson -Dmqtt); elsewhere open() fails
// saying so.
bool mqttAvailable();

class Publisher
{
public:
	virtual ~Publisher() = default;

	// Connects to `options.url` (false with `error` naming HOST:PORT and why).
	static bool open(const PublisherOptions &options, std::unique_ptr<Publisher> &out,
			 std::string &error);

	// Queues one message (libmosquitto copies it); false when it was dropped.
	virtual bool publish(const void *payload, size_t size) = 0;

	// Waits up to flushTimeoutMs for the queue to be acknowledged, then disconnects. Once.
	virtual void close() = 0;

	virtual PublisherCounts counts() const = 0;
	virtual bool connected() const = 0;
};

} // namespace calped::mqtt
