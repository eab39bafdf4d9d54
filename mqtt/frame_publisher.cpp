// SPDX-License-Identifier: BSD-2-Clause
#include "frame_publisher.h"

#include <chrono>

#include <unistd.h>

namespace calped::mqtt {

std::string defaultCameraId()
{
	char name[256] = {};
	if (gethostname(name, sizeof(name) - 1) != 0 || name[0] == '\0')
		return "camera";
	return name;
}

bool FramePublisher::open(const FramePublisherOptions &options, std::string &error)
{
	PublisherOptions p;
	if (!parseMqttUrl(options.url, p.url, error))
		return false;
	p.queueCapacity = options.queueCapacity;
	p.connectTimeoutMs = options.connectTimeoutMs;
	p.flushTimeoutMs = options.flushTimeoutMs;
	if (!Publisher::open(p, publisher_, error))
		return false;
	url_ = options.url;
	cameraId_ = options.cameraId.empty() ? defaultCameraId() : options.cameraId;
	return true;
}

bool FramePublisher::publish(apps::JsonFrame record, const Detections &detections)
{
	if (!publisher_)
		return false;
	record.camera = cameraId_.c_str();
	record.unixTime = std::chrono::duration<double>(
				  std::chrono::system_clock::now().time_since_epoch()).count();
	message_.clear();
	apps::writeJsonFrame(message_, record, detections, false);
	return publisher_->publish(message_.data(), message_.size());
}

void FramePublisher::close()
{
	if (!publisher_)
		return;
	publisher_->close();
	finalCounts_ = publisher_->counts();
}

PublisherCounts FramePublisher::counts() const
{
	return publisher_ ? publisher_->counts() : finalCounts_;
}

std::string FramePublisher::summary() const
{
	const PublisherCounts c = counts();
	auto n = [](uint64_t v) { return std::to_string(v); };
	return "mqtt " + url_ + ": frames " + n(c.offered) + ", sent " + n(c.sent) + ", acknowledged " +
	       n(c.acknowledged) + ", dropped " + n(c.dropped) + " (queue full), unacknowledged " +
	       n(c.unacknowledged()) + ", reconnects " + n(c.reconnects);
}

} // namespace calped::mqtt
