// SPDX-License-Identifier: BSD-2-Clause
// The one JSON frame record, written by calped-detect (--jsonl), calped-eval (--frames-jsonl),
// the live programs (standard output) and the MQTT publisher (one message per frame,
// docs/mqtt.md), one object per line (docs/cli.md):
//   {["camera":"..",]"frame":N[,"time":UNIX_SECONDS],"method":"calibrated"
//    [,"camera_estimate":E][,"file":"..."]
//    [,"timestamp_ns":T],"width":W,"height":H,"ms":M,"detections":[{"x":..,"y":..,"w":..,
//    "h":..,"score":..[,"ground_x":..,"ground_y":..][,"world_height":..]},...]}
// Strings are JSON-escaped (quotes, backslashes, every control character) and bytes that
// are not valid UTF-8 become U+FFFD, so any file name gives a valid line. The text goes to
// a JsonSink: a FILE (fputc/fwrite, nothing allocated) or a JsonBuffer, which grows to the
// longest record once and is then reused (the live loop and the publisher write every frame).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include <calped/detector.h>

namespace calped::apps {

struct JsonFrame {
	const char *camera = nullptr; // the camera's id (MQTT messages): written when not null
	long long frame = 0;
	double unixTime = -1;         // wall-clock seconds since 1970 (UTC): written when >= 0
	const char *method = "generic";
	const char *file = nullptr; // the input file: written when not null
	int64_t timestampNs = -1;   // a live source's timestamp: written when >= 0
	int width = 0, height = 0;
	double ms = 0; // the detector's own time, FrameStats::msTotal
	int cameraEstimate = -1; // --calib auto: the camera estimate used (0: none yet); written when >= 0
};

// Where the encoder writes.
class JsonSink
{
public:
	virtual void put(const char *text, size_t size) = 0;

protected:
	~JsonSink() = default;
};

class JsonFileSink final : public JsonSink
{
public:
	explicit JsonFileSink(FILE *f) : f_(f) {}
	void put(const char *text, size_t size) override { std::fwrite(text, 1, size, f_); }

private:
	FILE *f_;
};

// A reusable text buffer: clear() keeps the capacity, so after the longest record no write
// allocates.
class JsonBuffer final : public JsonSink
{
public:
	explicit JsonBuffer(size_t reserve = 0) { text_.reserve(reserve); }
	void put(const char *text, size_t size) override { text_.append(text, size); }
	void clear() { text_.clear(); }
	const char *data() const { return text_.data(); }
	size_t size() const { return text_.size(); }

private:
	std::string text_;
};

// One record; `newline` ends it with '\n' (JSON Lines; MQTT messages go without).
void writeJsonFrame(JsonSink &out, const JsonFrame &frame, const Detections &detections,
		    bool newline = true);
void writeJsonFrame(FILE *f, const JsonFrame &frame, const Detections &detections);

// The detections' array alone.
void writeJsonDetections(JsonSink &out, const Detections &detections);
void writeJsonDetections(FILE *f, const Detections &detections);

// `text` as a JSON string literal, quotes included, escaped as above.
void writeJsonString(JsonSink &out, const char *text, size_t size);
void writeJsonString(FILE *f, const char *text, size_t size);
std::string jsonString(const std::string &text);

} // namespace calped::apps
