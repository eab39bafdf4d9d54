// SPDX-License-Identifier: BSD-2-Clause
#include "live_loop.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "cli_error.h"
#include "frame_detector.h"
#include "detector_options.h"
#include "json_frame.h"
#include "mqtt_options.h"
#include "overlay_writer.h"
#include "stop_signal.h"

namespace calped {
namespace live {

using apps::cliFail;
using apps::kExitRuntime;
using apps::stopRequested;

namespace {

// Model, calibration and detector, set up before (or, when the source cannot tell its
// frame size, at) the first frame.
struct DetectorSetup {
	apps::DetectorInputs inputs;
	apps::FrameDetector detector;

	bool create(const LiveOptions &options, int width, int height, std::string &error)
	{
		std::string note;
		if (!detector.create(inputs.model, options.detector, width, height,
				     inputs.hasCamera ? &inputs.camera : nullptr, error, &note))
			return false;
		if (!note.empty())
			std::fprintf(stderr, "%s\n", note.c_str());
		return true;
	}
};

class StatsLine
{
public:
	explicit StatsLine(const char *program) : program_(program), last_(Clock::now()) {}

	bool due(double every) const
	{
		return std::chrono::duration<double>(Clock::now() - last_).count() >= every;
	}

	void print(const ports::SourceStats &s, uint64_t processed, const StatsReporter *extra)
	{
		const auto now = Clock::now();
		const double seconds = std::chrono::duration<double>(now - last_).count();
		const double fps = seconds > 0 ? (processed - lastProcessed_) / seconds : 0;
		char line[512];
		std::snprintf(line, sizeof(line),
			      "%s: %.1f fps, processed %llu, delivered %llu, dropped %llu, incomplete %llu, "
			      "timeouts %llu, restarts %llu",
			      program_, fps, static_cast<unsigned long long>(processed),
			      static_cast<unsigned long long>(s.delivered),
			      static_cast<unsigned long long>(s.dropped),
			      static_cast<unsigned long long>(s.incomplete),
			      static_cast<unsigned long long>(s.timeouts),
			      static_cast<unsigned long long>(s.restarts));
		if (extra) {
			const size_t used = std::strlen(line);
			extra->appendStats(line + used, sizeof(line) - used);
		}
		std::fprintf(stderr, "%s\n", line);
		last_ = now;
		lastProcessed_ = processed;
	}

private:
	using Clock = std::chrono::steady_clock;
	const char *program_;
	Clock::time_point last_;
	uint64_t lastProcessed_ = 0;
};

} // namespace

int runLive(ports::FrameSource &source, const LiveOptions &options, const char *program,
	    const StatsReporter *extra)
{
	// Before the first slow step, so a stop during setup is not a kill.
	apps::installStopHandlers();
	std::string error;
	DetectorSetup setup;
	if (!apps::loadDetectorInputs(options.detector, setup.inputs, error))
		return cliFail(program, kExitRuntime, error);
	int width = 0, height = 0;
	if (source.frameSize(width, height) && !setup.create(options, width, height, error))
		return cliFail(program, kExitRuntime, error);
	OverlayWriter overlay;
	if (!options.overlayDir.empty() && !overlay.open(options.overlayDir, error))
		return cliFail(program, kExitRuntime, error);
	// Before the source starts: an unreachable broker is an error at start.
	mqtt::FramePublisher publisher;
	if (!apps::openMqtt(options.mqtt, publisher, error))
		return cliFail(program, kExitRuntime, error);

	Status st = source.start();
	if (!st.ok())
		return cliFail(program, kExitRuntime, std::string(source.name()) + ": " + st.message());
	if (!options.quiet)
		std::fprintf(stderr, "%s: streaming from %s\n", program, source.name());

	StatsLine statsLine(program);
	uint64_t processed = 0;
	bool overlayWarned = false;
	std::vector<Detection> kept; // --min-score: grows to the most detections once
	apps::JsonFrame record;
	record.method = options.detector.methodName();
	int exitCode = 0;
	using Clock = std::chrono::steady_clock;
	Clock::time_point lastFrame = Clock::now(); // or the start: --frame-timeout counts from it
	while (!stopRequested()) {
		if (!options.quiet && statsLine.due(options.statsEvery))
			statsLine.print(source.stats(), processed, extra);

		ports::Frame frame;
		st = source.next(frame, static_cast<int>(options.timeoutMs));
		if (st.code() == ErrorCode::Timeout) {
			// Counted by the source; a stop signal is seen on the next turn. A camera that
			// only ever sends damaged frames (packet loss without resend) must not run for ever.
			const double waited = std::chrono::duration<double>(Clock::now() - lastFrame).count();
			if (options.frameTimeoutS > 0 && waited >= options.frameTimeoutS) {
				const ports::SourceStats s = source.stats();
				char line[200];
				std::snprintf(line, sizeof(line),
					      "no complete frame for %.1f s (%llu incomplete, %llu timeouts so far; "
					      "--frame-timeout %g)",
					      waited, static_cast<unsigned long long>(s.incomplete),
					      static_cast<unsigned long long>(s.timeouts), options.frameTimeoutS);
				exitCode = cliFail(program, kExitRuntime, std::string(source.name()) + ": " + line);
				break;
			}
			continue;
		}
		if (st.code() == ErrorCode::EndOfStream)
			break;
		if (!st.ok()) {
			exitCode = cliFail(program, kExitRuntime, std::string(source.name()) + ": " + st.message());
			break;
		}
		lastFrame = Clock::now();
		if (!setup.detector.valid() && !setup.create(options, frame.image.width, frame.image.height, error)) {
			exitCode = cliFail(program, kExitRuntime, error);
			break;
		}

		Detections dets;
		st = setup.detector.detect(frame.image, dets);
		if (st.code() == ErrorCode::ImageTooSmall) {
			dets = Detections(); // no window fits: no pedestrians, not a failure
		} else if (!st.ok()) {
			exitCode = cliFail(program, kExitRuntime,
					   "frame " + std::to_string(frame.id) + ": " + st.message());
			break;
		}
		dets = apps::filterByScore(dets, options.detector.minScore, kept);
		record.frame = static_cast<long long>(frame.id);
		record.timestampNs = frame.timestampNs;
		record.width = frame.image.width;
		record.height = frame.image.height;
		record.ms = st.ok() ? setup.detector.lastStats().msTotal : 0.0;
		record.method = setup.detector.methodName();
		record.cameraEstimate = setup.detector.cameraEstimate();
		if (const std::string change = setup.detector.estimateChange(); !change.empty())
			std::fprintf(stderr, "%s\n", change.c_str());
		apps::writeJsonFrame(stdout, record, dets);
		std::fflush(stdout); // live output: a reader sees each frame as it is processed
		if (publisher.isOpen())
			publisher.publish(record, dets); // a dropped message is counted, the loop goes on
		if (!options.overlayDir.empty() && processed % static_cast<uint64_t>(options.overlayEvery) == 0 &&
		    !overlay.write(frame, dets, error)) {
			if (error.compare(0, 8, "overlays") != 0) {
				exitCode = cliFail(program, kExitRuntime, error);
				break;
			}
			if (!overlayWarned)
				std::fprintf(stderr, "%s: warning: %s\n", program, error.c_str());
			overlayWarned = true;
		}
		source.release();
		processed++;
		if (options.frames > 0 && processed >= static_cast<uint64_t>(options.frames))
			break;
	}
	source.stop();
	apps::closeMqtt(publisher, program, options.quiet);
	if (std::fflush(stdout) != 0 || std::ferror(stdout))
		exitCode = cliFail(program, kExitRuntime, "cannot write standard output");
	if (!options.quiet)
		statsLine.print(source.stats(), processed, extra);
	if (exitCode == 0 && stopRequested())
		exitCode = apps::stopExitCode();
	return exitCode;
}

} // namespace live
} // namespace calped
