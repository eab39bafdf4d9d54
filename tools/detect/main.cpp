// SPDX-License-Identifier: BSD-2-Clause
// calped-detect: runs the detector over image files, folders or videos and writes CSV,
// MOTChallenge detections, JSON Lines and overlay images. See docs/cli.md.
#include <algorithm>
#include <cstdio>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <calped/calped.h>

#include "cli_error.h"
#include "detector_options.h"
#include "file_io.h"
#include "frame_detector.h"
#include "frame_list.h"
#include "image_io.h"
#include "image_prefetch.h"
#include "json_frame.h"
#include "mqtt_options.h"
#include "overlay.h"
#include "program.h"
#include "progress.h"
#include "stop_signal.h"
#include "video_pipe.h"
#include "writers.h"

namespace calped::apps {

namespace {

const ProgramInfo kProgram = {
	"calped-detect",
	"usage: calped-detect --model BLOB [options] INPUT...\n"
	"\n"
	"Runs the calped pedestrian detector. Each INPUT is an image file (PNG, JPEG, PPM,\n"
	"PGM), a folder whose *.png, *.jpg, *.jpeg, *.ppm and *.pgm files are taken in name\n"
	"order, or a video file (.avi, .mp4, .mkv, ... decoded by ffmpeg). Frames are numbered\n"
	"from 1 across the inputs. With --calib the calibrated method runs (docs/cli.md).\n"
	"\n"
	"options:\n",
	"\n"
	"SIGINT and SIGTERM stop after the current frame: the outputs end with that frame's\n"
	"complete lines, exit status 128 + the signal (130, 143).\n"
	"\n"
	"exit status: 0 success, 1 runtime error, 2 usage error, 130/143 stopped by a signal\n",
};

struct Options {
	DetectorOptions detector;
	std::string csvPath;
	std::string motPath;
	std::string jsonlPath; // "-" means standard output
	std::string overlayDir;
	long overlayEvery = 1;
	long maxFrames = 0; // 0 means every frame
	bool quiet = false;
	MqttOptions mqtt;
	std::vector<std::string> inputs;
};

std::vector<OptionSpec> optionTable()
{
	return joinOptions(joinOptions(detectorOptionTable(DetectorFlags::All), {
		{ "csv", "FILE", "write detections as CSV: frame,x,y,w,h,score,ground_x,ground_y,\n"
				 "world_height (world fields empty without --calib)" },
		{ "mot", "FILE", "write MOTChallenge detections: frame,-1,x,y,w,h,score,gx,gy,height\n"
				 "(-1 for the world fields without --calib)" },
		{ "jsonl", "FILE|-", "write one JSON object per frame (- for standard output)" },
		{ "overlay", "DIR", "write DIR/NNNNNN.png with the detections drawn in green" },
		{ "overlay-every", "K", "overlay only frames 1, 1+K, 1+2K, ... (default 1)" },
		{ "max-frames", "N", "stop after the first N frames" },
		{ "quiet", nullptr, "no progress, warnings or summary on standard error" },
	}), mqttOptionTable());
}

// -1 to go on, else the exit status.
int parseOptions(int argc, const char *const *argv, Options &out)
{
	ParsedArgs args;
	const int rc = parseCommandLine(kProgram, optionTable(), true, argc, argv, args,
					[&](const ParsedOption &o, std::string &e) {
						return takeDetectorOption(o, out.detector, e) ||
						       takeMqttOption(o, out.mqtt, e);
					});
	if (rc >= 0)
		return rc;
	std::string error;
	for (const ParsedOption &o : args.options) {
		const std::string &n = o.name;
		bool ok = true;
		if (n == "csv" || n == "mot" || n == "jsonl" || n == "overlay")
			ok = nonEmpty(o, "a file or folder name",
				      n == "csv" ? out.csvPath : n == "mot" ? out.motPath
						   : n == "jsonl" ? out.jsonlPath : out.overlayDir, error);
		else if (n == "overlay-every")
			ok = wholeIn(o, 1, 1000000000L, out.overlayEvery, error);
		else if (n == "max-frames")
			ok = wholeIn(o, 1, std::numeric_limits<long>::max(), out.maxFrames, error);
		else if (n == "quiet")
			out.quiet = true;
		if (!ok)
			return usageError(kProgram, error);
	}
	out.inputs = args.positional;
	if (!checkDetectorOptions(out.detector, true, DetectorFlags::All, error) ||
	    !checkMqttOptions(out.mqtt, error))
		return usageError(kProgram, error);
	if (out.inputs.empty())
		return usageError(kProgram, "no input images, folders or videos given (try --help)");
	const std::string *outputs[] = { &out.csvPath, &out.motPath, &out.jsonlPath };
	for (int i = 0; i < 3; i++)
		for (int j = i + 1; j < 3; j++)
			if (!outputs[i]->empty() && *outputs[i] == *outputs[j])
				return usageError(kProgram, "--csv, --mot and --jsonl must name different files");
	return -1;
}

int fail(int code, std::string message)
{
	return cliFail(kProgram.name, code, std::move(message));
}

// One frame source of the run: an image file or a video (frames follow each other).
struct Input {
	std::string path;
	bool video = false;
	int width = 0, height = 0; // a video's frame size (ffprobe)
};

bool listInputs(const std::vector<std::string> &paths, std::vector<Input> &out,
		std::string &error)
{
	for (const std::string &path : paths) {
		if (ports::isVideoFileName(path) && isRegularFile(path)) {
			out.push_back({ path, true });
			continue;
		}
		std::vector<std::string> files;
		if (!listFrames({ path }, files, error))
			return false;
		for (std::string &f : files)
			out.push_back({ std::move(f), false });
	}
	return true;
}

std::string frameLabel(long frame, const std::string &path)
{
	return "frame " + std::to_string(frame) + " (" + path + ")";
}

// Writes one frame's outputs; false with `error` when an overlay cannot be written.
struct Outputs {
	OutputFile csv, mot, jsonl;
	mqtt::FramePublisher mqtt; // --mqtt: one message per frame, the JSON Lines record
	std::string overlayDir;
	long overlayEvery = 1;

	bool write(long frame, const std::string &path, const FrameDetector &detector,
		   const RgbImage &image, double ms, const Detections &dets, std::string &error)
	{
		if (csv.isOpen())
			writeCsvRows(csv.get(), frame, dets);
		if (mot.isOpen())
			writeMotRows(mot.get(), frame, dets);
		JsonFrame record;
		record.frame = frame;
		record.method = detector.methodName();
		record.cameraEstimate = detector.cameraEstimate();
		record.file = path.c_str();
		record.width = image.width;
		record.height = image.height;
		record.ms = ms;
		if (jsonl.isOpen())
			writeJsonFrame(jsonl.get(), record, dets);
		if (mqtt.isOpen())
			mqtt.publish(record, dets); // a dropped message is counted, the run goes on
		if (!overlayDir.empty() && (frame - 1) % overlayEvery == 0)
			return writePng(overlayDir + "/" + overlayFileName(frame), renderOverlay(image, dets),
					error);
		return true;
	}
};

int run(const Options &opt)
{
	std::string error;
	std::vector<Input> inputs;
	if (!listInputs(opt.inputs, inputs, error))
		return fail(kExitRuntime, error);
	bool anyVideo = false;
	for (const Input &in : inputs)
		anyVideo = anyVideo || in.video;
	if (opt.maxFrames > 0 && static_cast<size_t>(opt.maxFrames) < inputs.size())
		inputs.resize(static_cast<size_t>(opt.maxFrames));

	// Headers only: finds undecodable files before any work and sizes the detector for
	// the largest frame, so frames of mixed sizes all fit.
	int maxW = 0, maxH = 0;
	ports::ImageDecoder decoder;
	for (Input &in : inputs) {
		int w = 0, h = 0;
		if (in.video) {
			const Status st = ports::probeVideo(in.path, w, h);
			if (!st.ok())
				return fail(kExitRuntime, st.message());
			in.width = w;
			in.height = h;
		} else if (!decoder.probe(in.path, w, h, error)) {
			return fail(kExitRuntime, error);
		}
		maxW = std::max(maxW, w);
		maxH = std::max(maxH, h);
	}

	DetectorInputs loaded;
	if (!loadDetectorInputs(opt.detector, loaded, error))
		return fail(kExitRuntime, error);
	FrameDetector detector;
	std::string note;
	if (!detector.create(loaded.model, opt.detector, maxW, maxH,
			     loaded.hasCamera ? &loaded.camera : nullptr, error, &note))
		return fail(kExitRuntime, error);
	if (!opt.quiet && !note.empty())
		std::fprintf(stderr, "%s: %s\n", kProgram.name, note.c_str());


	Outputs out;
	out.overlayDir = opt.overlayDir;
	out.overlayEvery = opt.overlayEvery;
	if (!opt.csvPath.empty()) {
		if (!out.csv.open(opt.csvPath, error))
			return fail(kExitRuntime, error);
		writeCsvHeader(out.csv.get());
	}
	if (!opt.motPath.empty() && !out.mot.open(opt.motPath, error))
		return fail(kExitRuntime, error);
	if (!opt.jsonlPath.empty() && !out.jsonl.open(opt.jsonlPath, error))
		return fail(kExitRuntime, error);
	if (!opt.overlayDir.empty() && !makeDirectories(opt.overlayDir, error))
		return fail(kExitRuntime, error);
	if (!openMqtt(opt.mqtt, out.mqtt, error))
		return fail(kExitRuntime, error);

	RunStats stats(anyVideo ? -1 : static_cast<long>(inputs.size()));
	RgbImage image;
	std::vector<Detection> kept;
	ports::VideoPipe pipe;
	// With more than one thread, the next image decodes while this one is detected.
	const bool prefetch = opt.detector.detectorThreads() > 1;
#if defined(__GLIBC__)
	// stb allocates and frees a frame-sized buffer per image: kept in the heap, not
	// mapped and unmapped (page faults) every frame, on whichever thread decodes.
	if (prefetch) {
		mallopt(M_MMAP_THRESHOLD, 256 << 20);
		mallopt(M_TRIM_THRESHOLD, 512 << 20);
	}
#endif
	ImagePrefetch next;
	long frame = 0;
	for (size_t index = 0; index < inputs.size(); index++) {
		const Input &in = inputs[index];
		if (in.video) {
			const Status st = pipe.open(in.path, in.width, in.height);
			if (!st.ok())
				return fail(kExitRuntime, st.message());
			image.width = in.width;
			image.height = in.height;
			image.pixels.resize(static_cast<size_t>(in.width) * in.height * 3);
		}
		for (;;) {
			if (opt.maxFrames > 0 && frame >= opt.maxFrames)
				break;
			if (stopRequested())
				break;
			if (in.video) {
				// Short waits, so that a stop signal is seen however slow ffmpeg is.
				Status st;
				do
					st = pipe.read(image.pixels.data(), 200);
				while (st.code() == ErrorCode::Timeout && !stopRequested());
				if (st.code() == ErrorCode::EndOfStream || st.code() == ErrorCode::Timeout)
					break;
				if (!st.ok())
					return fail(kExitRuntime, st.message());
			} else if (!next.take(in.path, image, error) &&
				   (!error.empty() || !decoder.decode(in.path, image, error))) {
				return fail(kExitRuntime, error);
			}
			frame++;
			if (prefetch && index + 1 < inputs.size() && !inputs[index + 1].video &&
			    (opt.maxFrames <= 0 || frame < opt.maxFrames))
				next.start(inputs[index + 1].path);

			Detections dets;
			Status st = detector.detect(
				ImageView::rgb8(image.pixels.data(), image.width, image.height), dets);
			if (st.code() == ErrorCode::ImageTooSmall) {
				// No window fits: the honest answer is "no pedestrians", not a failed run.
				if (!opt.quiet)
					std::fprintf(stderr, "calped-detect: warning: %s is smaller than the model window, no detections\n",
						     frameLabel(frame, in.path).c_str());
				dets = Detections();
			} else if (!st.ok()) {
				return fail(kExitRuntime, frameLabel(frame, in.path) + ": " + st.message());
			}
			const double ms = st.ok() ? detector.lastStats().msTotal : 0.0;
			dets = filterByScore(dets, opt.detector.minScore, kept);
			if (!out.write(frame, in.path, detector, image, ms, dets, error))
				return fail(kExitRuntime, error);
			if (const std::string change = detector.estimateChange(); !change.empty() && !opt.quiet)
				std::fprintf(stderr, "%s: frame %ld: %s\n", kProgram.name, frame, change.c_str());

			stats.addFrame(ms, dets.count);
			if (!opt.quiet && stats.progressDue())
				stats.printProgress();
			if (!in.video)
				break; // one frame per image
		}
		pipe.close();
		if (stopRequested())
			break;
	}
	if (frame == 0 && !stopRequested())
		return fail(kExitRuntime, "no frames in the inputs");

	closeMqtt(out.mqtt, kProgram.name, opt.quiet);
	if (!out.csv.close(error) || !out.mot.close(error) || !out.jsonl.close(error))
		return fail(kExitRuntime, error);
	if (!opt.quiet) {
		stats.printSummary(opt.detector.calibAuto() ? "auto" : opt.detector.methodName());
		if (!loaded.hasCamera && !opt.detector.calibAuto())
			std::fprintf(stderr, "%s: %s\n", kProgram.name, kGenericHint);
	}
	return stopRequested() ? stopExitCode() : 0;
}

} // namespace

} // namespace calped::apps

int main(int argc, char **argv)
{
	using namespace calped::apps;

	// SIGINT/SIGTERM finish the current frame; a closed pipe on --jsonl - becomes a
	// reported write error instead of a silent death.
	installStopHandlers();

	Options opt;
	const int rc = parseOptions(argc, argv, opt);
	if (rc >= 0)
		return rc;
	return runGuarded(kProgram.name, [&] { return run(opt); });
}
