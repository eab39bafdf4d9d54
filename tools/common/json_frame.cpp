// SPDX-License-Identifier: BSD-2-Clause
#include "json_frame.h"

#include <cinttypes>
#include <cmath>
#include <cstring>

namespace calped::apps {

namespace {

// Length of the valid UTF-8 sequence at s[0] (RFC 3629: no overlongs, no surrogates, at
// most U+10FFFF), or 0 when the bytes there are not one.
size_t utf8Length(const unsigned char *s, size_t left)
{
	const unsigned char c = s[0];
	size_t n;
	unsigned char lo = 0x80, hi = 0xbf;
	if (c < 0x80)
		return 1;
	if (c >= 0xc2 && c <= 0xdf) {
		n = 2;
	} else if (c >= 0xe0 && c <= 0xef) {
		n = 3;
		if (c == 0xe0)
			lo = 0xa0;
		if (c == 0xed)
			hi = 0x9f;
	} else if (c >= 0xf0 && c <= 0xf4) {
		n = 4;
		if (c == 0xf0)
			lo = 0x90;
		if (c == 0xf4)
			hi = 0x8f;
	} else {
		return 0;
	}
	if (left < n || s[1] < lo || s[1] > hi)
		return 0;
	for (size_t i = 2; i < n; i++)
		if (s[i] < 0x80 || s[i] > 0xbf)
			return 0;
	return n;
}

// Calls out(piece, length) for each piece of the escaped string, quotes excluded.
template <typename Out>
void escape(const char *text, size_t size, Out out)
{
	const unsigned char *s = reinterpret_cast<const unsigned char *>(text);
	for (size_t i = 0; i < size;) {
		const unsigned char c = s[i];
		char buf[8];
		if (c == '"' || c == '\\') {
			buf[0] = '\\';
			buf[1] = static_cast<char>(c);
			out(buf, 2);
			i++;
		} else if (c < 0x20 || c == 0x7f) {
			const char *named = c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t" : nullptr;
			if (named) {
				out(named, 2);
			} else {
				std::snprintf(buf, sizeof(buf), "\\u%04x", c);
				out(buf, 6);
			}
			i++;
		} else {
			const size_t n = utf8Length(s + i, size - i);
			if (n == 0) {
				out("\xef\xbf\xbd", 3); // U+FFFD REPLACEMENT CHARACTER, for one bad byte
				i++;
			} else {
				out(text + i, n);
				i += n;
			}
		}
	}
}

} // namespace

void writeJsonString(FILE *f, const char *text, size_t size)
{
	std::fputc('"', f);
	escape(text, size, [f](const char *p, size_t n) { std::fwrite(p, 1, n, f); });
	std::fputc('"', f);
}

std::string jsonString(const std::string &text)
{
	std::string out = "\"";
	escape(text.data(), text.size(), [&out](const char *p, size_t n) { out.append(p, n); });
	return out + "\"";
}

void writeJsonDetections(FILE *f, const Detections &detections)
{
	std::fputc('[', f);
	bool first = true;
	for (const Detection &d : detections) {
		std::fprintf(f, "%s{\"x\":%.2f,\"y\":%.2f,\"w\":%.2f,\"h\":%.2f,\"score\":%.4f",
			     first ? "" : ",", d.x, d.y, d.w, d.h, d.score);
		// With a calibration: where the person stands (metres) and how tall the box is.
		if (std::isfinite(d.groundX) && std::isfinite(d.groundY))
			std::fprintf(f, ",\"ground_x\":%.3f,\"ground_y\":%.3f", d.groundX, d.groundY);
		if (std::isfinite(d.worldHeight))
			std::fprintf(f, ",\"world_height\":%.3f", d.worldHeight);
		std::fputc('}', f);
		first = false;
	}
	std::fputc(']', f);
}

void writeJsonFrame(FILE *f, const JsonFrame &fr, const Detections &detections)
{
	std::fprintf(f, "{\"frame\":%lld,\"method\":", fr.frame);
	writeJsonString(f, fr.method, std::strlen(fr.method));
	if (fr.cameraEstimate >= 0)
		std::fprintf(f, ",\"camera_estimate\":%d", fr.cameraEstimate);
	if (fr.file) {
		std::fputs(",\"file\":", f);
		writeJsonString(f, fr.file, std::strlen(fr.file));
	}
	if (fr.timestampNs >= 0)
		std::fprintf(f, ",\"timestamp_ns\":%" PRId64, fr.timestampNs);
	std::fprintf(f, ",\"width\":%d,\"height\":%d,\"ms\":%.3f,\"detections\":", fr.width, fr.height,
		     fr.ms);
	writeJsonDetections(f, detections);
	std::fputs("}\n", f);
}

} // namespace calped::apps
