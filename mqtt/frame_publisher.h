// SPDX-License-Identifier: BSD-2-Clause
// One MQTT message per frame (docs/mqtt.md): the JSON frame record (tools/json) with the
// camera's id and the wall-clock time, published through a Publisher. Shared by
// calped-detect, the live programs and the GStreamer element.
#pragma once

#include <memory>
#include <string>

#include <calped/detector.h>

#include "json_frame.h"
#include "publisher.h"

namespace calped::mqtt {

struct FramePublisherOptions {
	std::string url;      // mqtt://HOST[:PORT]/TOPIC
	std::string cameraId; // empty: defaultCameraId()
	size_t queueCapacity = 1000;
	int connectTimeoutMs = 5000;
	int flushTimeoutMs = 5000;
};

// The host's name (gethostname), or "camera" where it has none: one camera per host is
// the fleet's usual layout (docs/deploying.md).
std::string defaultCameraId();

class FramePublisher
{
public:
	// Parses the URL and connects; false with `error` (a bad URL, an unreachable broker).
	bool open(const FramePublisherOptions &options, std::string &error);
	bool isOpen() const { return publisher_ != nullptr; }

	// Encodes `record` (camera and time filled in here) and publishes it; false when the
	// message was dropped (counted). The buffer grows to the longest message once.
	bool publish(apps::JsonFrame record, const Detections &detections);

	// Flushes and disconnects (Publisher::close); the counts stay readable.
	void close();

	PublisherCounts counts() const;
	const std::string &cameraId() const { return cameraId_; }

	// "mqtt mqtt://HOST:PORT/TOPIC: frames F, sent S, acknowledged A, dropped D (queue
	// full), unacknowledged U, reconnects R": the line the programs print at exit.
	std::string summary() const;

private:
	std::string url_, cameraId_;
	std::unique_ptr<Publisher> publisher_;
	PublisherCounts finalCounts_;
	apps::JsonBuffer message_{ 4096 };
};

} // namespace calped::mqtt
