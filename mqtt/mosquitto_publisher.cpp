// SPDX-License-Identifier: BSD-2-Clause
// Publisher over libmosquitto (Debian libmosquitto-dev, 2.0): its network thread
// (mosquitto_loop_start) connects, reconnects and resends; this file counts.
#include "publisher.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>

#include <mosquitto.h>

namespace calped::mqtt {

namespace {

// MQTT keep-alive: a broker that vanished without closing the connection is noticed
// within 1.5 times this.
constexpr int kKeepAliveSeconds = 10;

void initLibrary()
{
	static std::once_flag once;
	std::call_once(once, [] { mosquitto_lib_init(); });
}

std::string errorText(int rc, int savedErrno)
{
	return rc == MOSQ_ERR_ERRNO ? std::strerror(savedErrno) : mosquitto_strerror(rc);
}

std::string seconds(int ms)
{
	char text[32];
	std::snprintf(text, sizeof(text), "%g s", ms / 1000.0);
	return text;
}

class MosquittoPublisher final : public Publisher
{
public:
	explicit MosquittoPublisher(const PublisherOptions &options) : options_(options) {}

	~MosquittoPublisher() override
	{
		close();
		if (mosq_)
			mosquitto_destroy(mosq_);
	}

	bool start(std::string &error)
	{
		initLibrary();
		const std::string where = "MQTT broker " + options_.url.hostPort();
		// A clean session with a generated id: what the publisher has not had acknowledged
		// lives in its own queue, not in the broker's memory of it.
		mosq_ = mosquitto_new(nullptr, true, this);
		if (!mosq_) {
			error = "cannot create an MQTT client: " + std::string(std::strerror(errno));
			return false;
		}
		mosquitto_int_option(mosq_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
		mosquitto_reconnect_delay_set(mosq_, 1, 8, true);
		// One message in flight at a time keeps the order across a reconnection: with more,
		// a message published between the new connection and the broker's CONNACK goes out
		// before the older ones libmosquitto resends after it (seen in tests/mqtt). The
		// cost is one round trip per message (docs/mqtt.md).
		mosquitto_int_option(mosq_, MOSQ_OPT_SEND_MAXIMUM, 1);
		mosquitto_connect_callback_set(mosq_, onConnect);
		mosquitto_disconnect_callback_set(mosq_, onDisconnect);
		mosquitto_publish_callback_set(mosq_, onPublish);

		int rc = mosquitto_connect_async(mosq_, options_.url.host.c_str(), options_.url.port,
						 kKeepAliveSeconds);
		if (rc != MOSQ_ERR_SUCCESS) {
			error = "cannot connect to the " + where + ": " + errorText(rc, errno);
			return false;
		}
		rc = mosquitto_loop_start(mosq_);
		if (rc != MOSQ_ERR_SUCCESS) {
			error = "cannot start the MQTT network thread: " + errorText(rc, errno);
			return false;
		}
		loopRunning_ = true;

		std::unique_lock<std::mutex> lock(mutex_);
		const bool answered = changed_.wait_for(lock, std::chrono::milliseconds(options_.connectTimeoutMs),
							[this] { return connack_ >= 0 || lostBeforeConnack_; });
		const int connack = connack_;
		const bool lost = lostBeforeConnack_;
		const int lostRc = lostRc_;
		lock.unlock();
		if (answered && connack == 0)
			return true;
		stopLoop();
		if (!answered)
			error = "no answer from the " + where + " within " + seconds(options_.connectTimeoutMs) +
				" (is it running and reachable?)";
		else if (lost)
			error = "cannot connect to the " + where + ": " + mosquitto_strerror(lostRc);
		else
			error = "the " + where + " refused the connection: " + mosquitto_connack_string(connack);
		return false;
	}

	bool publish(const void *payload, size_t size) override
	{
		offered_++;
		if (sent_.load() - acknowledged_.load() >= options_.queueCapacity || closed_) {
			dropped_++;
			return false;
		}
		// Counted before the call: the acknowledgement may arrive before it returns.
		sent_++;
		const int rc = mosquitto_publish(mosq_, nullptr, options_.url.topic.c_str(),
						 static_cast<int>(size), payload, 1, false);
		// MOSQ_ERR_NO_CONN comes after the message was queued (libmosquitto 2.0 queues a
		// QoS 1 message first, then tries to send it): it is resent on reconnection, so it
		// is in the queue. Every other error is a refusal before queueing.
		if (rc != MOSQ_ERR_SUCCESS && rc != MOSQ_ERR_NO_CONN) {
			sent_--;
			dropped_++;
			return false;
		}
		return true;
	}

	void close() override
	{
		if (closed_ || !loopRunning_)
			return;
		closed_ = true;
		{
			std::unique_lock<std::mutex> lock(mutex_);
			changed_.wait_for(lock, std::chrono::milliseconds(options_.flushTimeoutMs),
					  [this] { return acknowledged_.load() >= sent_.load(); });
		}
		mosquitto_disconnect(mosq_);
		stopLoop();
	}

	PublisherCounts counts() const override
	{
		PublisherCounts c;
		c.offered = offered_;
		c.sent = sent_.load();
		c.acknowledged = acknowledged_.load();
		c.dropped = dropped_;
		const uint64_t connections = connections_.load();
		c.reconnects = connections > 0 ? connections - 1 : 0;
		return c;
	}

	bool connected() const override { return connected_.load(); }

private:
	static MosquittoPublisher &self(void *user) { return *static_cast<MosquittoPublisher *>(user); }

	static void onConnect(struct mosquitto *, void *user, int rc)
	{
		MosquittoPublisher &p = self(user);
		std::lock_guard<std::mutex> lock(p.mutex_);
		if (p.connack_ < 0 || rc == 0)
			p.connack_ = rc;
		if (rc == 0) {
			p.connected_.store(true);
			p.connections_++;
		}
		p.changed_.notify_all();
	}

	static void onDisconnect(struct mosquitto *, void *user, int rc)
	{
		MosquittoPublisher &p = self(user);
		std::lock_guard<std::mutex> lock(p.mutex_);
		p.connected_.store(false);
		if (p.connack_ < 0 && !p.lostBeforeConnack_) {
			p.lostBeforeConnack_ = true;
			p.lostRc_ = rc;
		}
		p.changed_.notify_all();
	}

	static void onPublish(struct mosquitto *, void *user, int)
	{
		MosquittoPublisher &p = self(user);
		std::lock_guard<std::mutex> lock(p.mutex_);
		p.acknowledged_++;
		p.changed_.notify_all();
	}

	void stopLoop()
	{
		if (!loopRunning_)
			return;
		// Not forced: the thread leaves its reconnect wait when told to stop.
		mosquitto_loop_stop(mosq_, false);
		loopRunning_ = false;
	}

	const PublisherOptions options_;
	struct mosquitto *mosq_ = nullptr;
	bool loopRunning_ = false;
	bool closed_ = false;

	std::mutex mutex_;
	std::condition_variable changed_;
	int connack_ = -1; // the first CONNACK's code, -1 before one
	bool lostBeforeConnack_ = false;
	int lostRc_ = 0; // on_disconnect's code then
	std::atomic<bool> connected_{ false };
	std::atomic<uint64_t> connections_{ 0 };
	std::atomic<uint64_t> sent_{ 0 };
	std::atomic<uint64_t> acknowledged_{ 0 };
	uint64_t offered_ = 0, dropped_ = 0; // the publishing thread's only
};

} // namespace

bool mqttAvailable()
{
	return true;
}

bool Publisher::open(const PublisherOptions &options, std::unique_ptr<Publisher> &out,
		     std::string &error)
{
	if (options.queueCapacity == 0) {
		error = "the MQTT queue capacity must be at least 1";
		return false;
	}
	auto publisher = std::make_unique<MosquittoPublisher>(options);
	if (!publisher->start(error))
		return false;
	out = std::move(publisher);
	return true;
}

} // namespace calped::mqtt
