// SPDX-License-Identifier: BSD-2-Clause
#include "json_frame.h"

#include "excerpt.h" // utf8CharLength: the one UTF-8 check

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cmath>
#include <cstring>

namespace calped::apps {

namespace {

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
			const size_t n = utf8CharLength(s + i, size - i);
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


// snprintf into a stack buffer, then to the sink: every piece printed here is one number
// or a few fixed keys, far below the buffer's size.
__attribute__((format(printf, 2, 3))) void printTo(JsonSink &out, const char *format, ...)
{
	char buf[256];
	va_list args;
	va_start(args, format);
	const int n = std::vsnprintf(buf, sizeof(buf), format, args);
	va_end(args);
	if (n > 0)
		out.put(buf, std::min(static_cast<size_t>(n), sizeof(buf) - 1));
}

} // namespace

void writeJsonString(JsonSink &out, const char *text, size_t size)
{
	out.put("\"", 1);
	escape(text, size, [&out](const char *p, size_t n) { out.put(p, n); });
	out.put("\"", 1);
}

void writeJsonString(FILE *f, const char *text, size_t size)
{
	JsonFileSink out(f);
	writeJsonString(out, text, size);
}

std::string jsonString(const std::string &text)
{
	JsonBuffer out(text.size() + 2);
	writeJsonString(out, text.data(), text.size());
	return std::string(out.data(), out.size());
}

void writeJsonDetections(JsonSink &out, const Detections &detections)
{
	out.put("[", 1);
	bool first = true;
	for (const Detection &d : detections) {
		printTo(out, "%s{\"x\":%.2f,\"y\":%.2f,\"w\":%.2f,\"h\":%.2f,\"score\":%.4f",
			first ? "" : ",", d.x, d.y, d.w, d.h, d.score);
		// With a calibration: where the person stands (metres) and how tall the box is.
		if (std::isfinite(d.groundX) && std::isfinite(d.groundY))
			printTo(out, ",\"ground_x\":%.3f,\"ground_y\":%.3f", d.groundX, d.groundY);
		if (std::isfinite(d.worldHeight))
			printTo(out, ",\"world_height\":%.3f", d.worldHeight);
		out.put("}", 1);
		first = false;
	}
	out.put("]", 1);
}

void writeJsonDetections(FILE *f, const Detections &detections)
{
	JsonFileSink out(f);
	writeJsonDetections(out, detections);
}

void writeJsonFrame(JsonSink &out, const JsonFrame &fr, const Detections &detections, bool newline)
{
	out.put("{", 1);
	if (fr.camera) {
		out.put("\"camera\":", 9);
		writeJsonString(out, fr.camera, std::strlen(fr.camera));
		out.put(",", 1);
	}
	printTo(out, "\"frame\":%lld", fr.frame);
	if (fr.unixTime >= 0)
		printTo(out, ",\"time\":%.6f", fr.unixTime);
	out.put(",\"method\":", 10);
	writeJsonString(out, fr.method, std::strlen(fr.method));
	if (fr.cameraEstimate >= 0)
		printTo(out, ",\"camera_estimate\":%d", fr.cameraEstimate);
	if (fr.file) {
		out.put(",\"file\":", 8);
		writeJsonString(out, fr.file, std::strlen(fr.file));
	}
	if (fr.timestampNs >= 0)
		printTo(out, ",\"timestamp_ns\":%" PRId64, fr.timestampNs);
	printTo(out, ",\"width\":%d,\"height\":%d,\"ms\":%.3f,\"detections\":", fr.width, fr.height,
		fr.ms);
	writeJsonDetections(out, detections);
	out.put(newline ? "}\n" : "}", newline ? 2 : 1);
}

void writeJsonFrame(FILE *f, const JsonFrame &frame, const Detections &detections)
{
	JsonFileSink out(f);
	writeJsonFrame(out, frame, detections, true);
}

} // namespace calped::apps
