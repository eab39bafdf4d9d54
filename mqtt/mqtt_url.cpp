// SPDX-License-Identifier: BSD-2-Clause
#include "mqtt_url.h"

#include <cctype>

namespace calped::mqtt {

namespace {

bool fail(std::string &error, const std::string &text, const std::string &why)
{
	error = "bad MQTT URL '" + text + "': " + why + " (expected mqtt://HOST[:PORT]/TOPIC)";
	return false;
}

bool validUtf8(const std::string &s)
{
	for (size_t i = 0; i < s.size();) {
		const unsigned char c = static_cast<unsigned char>(s[i]);
		size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
		if (n == 0 || i + n > s.size())
			return false;
		for (size_t k = 1; k < n; k++)
			if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2)
				return false;
		i += n;
	}
	return true;
}

bool hostCharacter(char c)
{
	return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_';
}

} // namespace

std::string MqttUrl::hostPort() const
{
	const bool v6 = host.find(':') != std::string::npos;
	return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

bool parseMqttUrl(const std::string &text, MqttUrl &out, std::string &error)
{
	const std::string scheme = "mqtt://";
	if (text.compare(0, scheme.size(), scheme) != 0)
		return fail(error, text, text.find("://") != std::string::npos
						 ? "only the mqtt:// scheme is supported (no TLS)"
						 : "no mqtt:// scheme");
	const size_t slash = text.find('/', scheme.size());
	const std::string authority = text.substr(scheme.size(), slash == std::string::npos
								 ? std::string::npos : slash - scheme.size());
	if (authority.find('@') != std::string::npos)
		return fail(error, text, "user names and passwords are not supported");
	MqttUrl url;
	std::string portText;
	if (!authority.empty() && authority[0] == '[') {
		const size_t close = authority.find(']');
		if (close == std::string::npos)
			return fail(error, text, "'[' without ']' around an IPv6 address");
		url.host = authority.substr(1, close - 1);
		const std::string after = authority.substr(close + 1);
		if (!after.empty() && after[0] != ':')
			return fail(error, text, "unexpected '" + after + "' after the IPv6 address");
		if (!after.empty())
			portText = after.substr(1);
		for (char c : url.host)
			if (!std::isxdigit(static_cast<unsigned char>(c)) && c != ':' && c != '.')
				return fail(error, text, "bad IPv6 address '" + url.host + "'");
	} else {
		const size_t colon = authority.find(':');
		url.host = authority.substr(0, colon);
		if (colon != std::string::npos)
			portText = authority.substr(colon + 1);
		for (char c : url.host)
			if (!hostCharacter(c))
				return fail(error, text, "bad character '" + std::string(1, c) + "' in the host name");
	}
	if (url.host.empty())
		return fail(error, text, "no host");
	if (authority.find(':') != std::string::npos && authority.back() == ':')
		return fail(error, text, "':' without a port");
	if (!portText.empty()) {
		long port = 0;
		for (char c : portText) {
			if (!std::isdigit(static_cast<unsigned char>(c)) || port > 65535)
				return fail(error, text, "the port must be a number from 1 to 65535, got '" + portText + "'");
			port = port * 10 + (c - '0');
		}
		if (port < 1 || port > 65535)
			return fail(error, text, "the port must be a number from 1 to 65535, got '" + portText + "'");
		url.port = static_cast<int>(port);
	}
	if (slash == std::string::npos || slash + 1 >= text.size())
		return fail(error, text, "no topic after the host");
	url.topic = text.substr(slash + 1);
	if (url.topic.find('#') != std::string::npos)
		return fail(error, text, "'#' is a subscription wildcard (or a fragment), not allowed in a topic to publish to");
	if (url.topic.find('+') != std::string::npos)
		return fail(error, text, "'+' is a subscription wildcard, not allowed in a topic to publish to");
	if (url.topic.find('?') != std::string::npos)
		return fail(error, text, "queries ('?') are not supported");
	if (url.topic.find('\0') != std::string::npos || !validUtf8(url.topic))
		return fail(error, text, "the topic must be UTF-8 without NUL");
	for (char c : url.topic)
		if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
			return fail(error, text, "control characters in the topic");
	if (url.topic.size() > 65535)
		return fail(error, text, "the topic is longer than 65535 bytes");
	out = url;
	return true;
}

} // namespace calped::mqtt
