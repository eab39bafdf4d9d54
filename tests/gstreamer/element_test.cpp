// SPDX-License-Identifier: BSD-2-Clause
// The `calped` GStreamer element with the real GStreamer (docs/gstreamer.md):
// registration (gst-inspect-1.0), a pipeline to EOS (gst-launch-1.0), the metas of the
// first frames of the PETS video against a calped::Detector run on the very buffers the
// pipeline delivered (RGB and NV12), the bus messages, the element's time against the
// detector's own, and the errors. The environment (tests/gstreamer/meson.build) points
// GST_PLUGIN_PATH at the build and GST_REGISTRY at a registry file in the build folder.
// Cases skip, saying why, without the model, the calibration, the video, GStreamer's tools
// or the decoder plugins.
#include <gst/app/gstappsink.h>
#include <gst/gst.h>
#include <gst/video/gstvideometa.h>
#include <gst/video/video.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/model.h>

#include "common/alloc_counter.h"
#include "test_data.h"

namespace {

using namespace calped;

std::string env(const char *name)
{
	const char *v = std::getenv(name);
	return v ? v : "";
}

bool exists(const std::string &path)
{
	return !path.empty() && g_file_test(path.c_str(), G_FILE_TEST_EXISTS);
}

bool sanitized()
{
	return env("CALPED_GST_SANITIZED") == "1";
}

std::string videoPath()
{
	const std::string p = env("CALPED_SOURCE_DIR") + "/data/pets/vtest.avi";
	return exists(p) ? p : "";
}

std::string calibrationPath()
{
	const std::string shared = test::sharedDir();
	const std::string p = shared + "/data/pets2009-s2l1/View_001.xml";
	return !shared.empty() && exists(p) ? p : "";
}

// Skips the test unless the model, the calibration and (with `video`) the PETS video and
// the plugins that decode it are there.
#define REQUIRE_INPUTS(video)                                                                        \
	do {                                                                                          \
		if (test::inriaModelBlob().empty())                                                       \
			GTEST_SKIP() << "no INRIA model blob (needs ../shared and calped-convert)";          \
		if (calibrationPath().empty())                                                            \
			GTEST_SKIP() << "no ../shared/data/pets2009-s2l1/View_001.xml";                     \
		if ((video) && videoPath().empty())                                                       \
			GTEST_SKIP() << "no data/pets/vtest.avi (scripts/fetch-pets.sh)";                   \
		if ((video) && !haveElements({ "filesrc", "decodebin", "avidemux", "avdec_msmpeg4",      \
					      "videoconvert", "appsink" }))                               \
			GTEST_SKIP() << "missing GStreamer plugins (gstreamer1.0-plugins-base, -good, "     \
					"gstreamer1.0-libav)";                                                \
	} while (0)

bool haveElements(std::initializer_list<const char *> names)
{
	for (const char *n : names) {
		GstElementFactory *f = gst_element_factory_find(n);
		if (!f)
			return false;
		gst_object_unref(f);
	}
	return true;
}

// A GStreamer command line tool; false when it is not installed.
struct ToolRun {
	bool found = false;
	int exitStatus = -1;
	std::string out, err;
};

ToolRun runTool(const std::vector<std::string> &args)
{
	ToolRun r;
	gchar *path = g_find_program_in_path(args[0].c_str());
	if (!path)
		return r;
	r.found = true;
	std::vector<gchar *> argv;
	argv.push_back(path);
	for (size_t i = 1; i < args.size(); i++)
		argv.push_back(const_cast<gchar *>(args[i].c_str()));
	argv.push_back(nullptr);
	gchar *out = nullptr, *err = nullptr;
	gint status = 0;
	GError *error = nullptr;
	if (g_spawn_sync(nullptr, argv.data(), nullptr, G_SPAWN_DEFAULT, nullptr, nullptr, &out, &err,
			 &status, &error)) {
		r.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
		r.out = out ? out : "";
		r.err = err ? err : "";
	} else {
		r.err = error->message;
		g_error_free(error);
	}
	g_free(out);
	g_free(err);
	g_free(path);
	return r;
}

std::string elementArgs()
{
	return "model=" + test::inriaModelBlob() + " calibration=" + calibrationPath() + " resize=2";
}

// --- the frames a pipeline delivered, and what the element said about them ---

struct RoiRecord {
	std::string type;
	int id = -1, parentId = 0;
	unsigned x = 0, y = 0, w = 0, h = 0;
	bool hasParams = false;
	double score = NAN;
	bool hasGround = false, hasHeight = false;
	double groundX = NAN, groundY = NAN, worldHeight = NAN;
};

struct FrameRecord {
	int width = 0, height = 0;
	GstVideoFormat format = GST_VIDEO_FORMAT_UNKNOWN;
	GstVideoColorimetry colorimetry{};
	// Each plane copied with the frame's own stride and rows.
	std::vector<std::vector<uint8_t>> planes;
	std::vector<int> strides;
	GstClockTime pts = GST_CLOCK_TIME_NONE;
	std::vector<RoiRecord> rois;
};

struct MessageRecord {
	guint64 frame = 0, pts = 0;
	int count = -1;
	std::string method;
	double ms = -1, msElement = -1;
};

struct PipelineRun {
	std::vector<FrameRecord> frames;
	std::vector<MessageRecord> messages;
	std::string error; // the first error on the bus
};

double doubleField(const GstStructure *s, const char *name, bool &present)
{
	double v = NAN;
	present = gst_structure_get_double(s, name, &v);
	return v;
}

FrameRecord recordFrame(GstSample *sample)
{
	FrameRecord r;
	GstVideoInfo info;
	EXPECT_TRUE(gst_video_info_from_caps(&info, gst_sample_get_caps(sample)));
	GstBuffer *buf = gst_sample_get_buffer(sample);
	GstVideoFrame frame;
	EXPECT_TRUE(gst_video_frame_map(&frame, &info, buf, GST_MAP_READ));
	r.width = GST_VIDEO_FRAME_WIDTH(&frame);
	r.height = GST_VIDEO_FRAME_HEIGHT(&frame);
	r.format = GST_VIDEO_FRAME_FORMAT(&frame);
	r.colorimetry = info.colorimetry;
	for (guint p = 0; p < GST_VIDEO_FRAME_N_PLANES(&frame); p++) {
		const int stride = GST_VIDEO_FRAME_PLANE_STRIDE(&frame, p);
		const int rows = GST_VIDEO_FRAME_COMP_HEIGHT(&frame, p); // plane p holds component p here
		const uint8_t *data = static_cast<const uint8_t *>(GST_VIDEO_FRAME_PLANE_DATA(&frame, p));
		r.planes.emplace_back(data, data + static_cast<size_t>(stride) * rows);
		r.strides.push_back(stride);
	}
	gst_video_frame_unmap(&frame);
	r.pts = GST_BUFFER_PTS(buf);

	gpointer state = nullptr;
	GstMeta *meta;
	while ((meta = gst_buffer_iterate_meta_filtered(buf, &state,
							 GST_VIDEO_REGION_OF_INTEREST_META_API_TYPE))) {
		const auto *m = reinterpret_cast<GstVideoRegionOfInterestMeta *>(meta);
		RoiRecord roi;
		roi.type = g_quark_to_string(m->roi_type);
		roi.id = m->id;
		roi.parentId = m->parent_id;
		roi.x = m->x;
		roi.y = m->y;
		roi.w = m->w;
		roi.h = m->h;
		const GstStructure *s =
			gst_video_region_of_interest_meta_get_param(const_cast<GstVideoRegionOfInterestMeta *>(m), "detection");
		roi.hasParams = s != nullptr;
		if (s) {
			bool present = false, gy = false;
			roi.score = doubleField(s, "score", present);
			EXPECT_TRUE(present);
			roi.groundX = doubleField(s, "ground-x", roi.hasGround);
			roi.groundY = doubleField(s, "ground-y", gy);
			EXPECT_EQ(roi.hasGround, gy);
			roi.worldHeight = doubleField(s, "world-height", roi.hasHeight);
		}
		r.rois.push_back(roi);
	}
	return r;
}

void recordMessage(GstMessage *msg, PipelineRun &run)
{
	if (GST_MESSAGE_TYPE(msg) == GST_MESSAGE_ERROR) {
		GError *err = nullptr;
		gchar *dbg = nullptr;
		gst_message_parse_error(msg, &err, &dbg);
		if (run.error.empty())
			run.error = std::string(err->message) + (dbg ? std::string(" (") + dbg + ")" : "");
		g_error_free(err);
		g_free(dbg);
		return;
	}
	const GstStructure *s = gst_message_get_structure(msg);
	if (GST_MESSAGE_TYPE(msg) != GST_MESSAGE_ELEMENT || !gst_structure_has_name(s, "calped-detections"))
		return;
	MessageRecord m;
	EXPECT_TRUE(gst_structure_get_uint64(s, "frame", &m.frame));
	EXPECT_TRUE(gst_structure_get_uint64(s, "pts", &m.pts));
	EXPECT_TRUE(gst_structure_get_int(s, "count", &m.count));
	const gchar *method = gst_structure_get_string(s, "method");
	m.method = method ? method : "";
	EXPECT_TRUE(gst_structure_get_double(s, "ms", &m.ms));
	EXPECT_TRUE(gst_structure_get_double(s, "ms-element", &m.msElement));
	run.messages.push_back(m);
}

// Runs `description` (it must end in "appsink name=sink") for `frames` samples, then stops.
PipelineRun runPipeline(const std::string &description, int frames)
{
	PipelineRun run;
	GError *err = nullptr;
	GstElement *pipeline = gst_parse_launch(description.c_str(), &err);
	if (!pipeline) {
		ADD_FAILURE() << "gst_parse_launch: " << (err ? err->message : "?");
		if (err)
			g_error_free(err);
		return run;
	}
	GstElement *sink = gst_bin_get_by_name(GST_BIN(pipeline), "sink");
	GstBus *bus = gst_element_get_bus(pipeline);
	gst_element_set_state(pipeline, GST_STATE_PLAYING);
	const GstMessageType types = static_cast<GstMessageType>(GST_MESSAGE_ELEMENT | GST_MESSAGE_ERROR);
	const gint64 deadline = g_get_monotonic_time() + 60 * G_TIME_SPAN_SECOND;
	while (static_cast<int>(run.frames.size()) < frames && run.error.empty() &&
	       g_get_monotonic_time() < deadline) {
		GstSample *sample = gst_app_sink_try_pull_sample(GST_APP_SINK(sink), GST_SECOND / 10);
		GstMessage *msg;
		while ((msg = gst_bus_pop_filtered(bus, types))) {
			recordMessage(msg, run);
			gst_message_unref(msg);
		}
		if (sample) {
			run.frames.push_back(recordFrame(sample));
			gst_sample_unref(sample);
		} else if (gst_app_sink_is_eos(GST_APP_SINK(sink))) {
			break;
		}
	}
	gst_element_set_state(pipeline, GST_STATE_NULL);
	gst_object_unref(bus);
	gst_object_unref(sink);
	gst_object_unref(pipeline);
	return run;
}

std::string videoPipeline(const char *format, const std::string &calpedArgs)
{
	return "filesrc location=" + videoPath() + " ! decodebin ! videoconvert ! video/x-raw,format=" +
	       format + " ! calped " + calpedArgs + " ! appsink name=sink sync=false max-buffers=4";
}

// A caps format and what it is for calped: the test's own table, not the element's.
struct CapsFormat {
	const char *caps;
	PixelFormat format;
	bool yuv;
};

// The test's own view of a recorded frame (not the element's mapping code).
ImageView viewOf(const FrameRecord &f, const CapsFormat &caps)
{
	ImageView v;
	for (size_t p = 0; p < f.planes.size() && p < 3; p++) {
		v.planes[p] = f.planes[p].data();
		v.strides[p] = f.strides[p];
	}
	v.width = f.width;
	v.height = f.height;
	v.format = caps.format;
	EXPECT_STREQ(gst_video_format_to_string(f.format), caps.caps);
	if (caps.yuv) {
		// No colorimetry in the caps: GStreamer's default for SD video is BT.601, limited.
		EXPECT_EQ(f.colorimetry.matrix, GST_VIDEO_COLOR_MATRIX_BT601);
		EXPECT_EQ(f.colorimetry.range, GST_VIDEO_COLOR_RANGE_16_235);
		v.yuv = YuvEncoding::Bt601Limited;
	}
	return v;
}

unsigned roundedEdge(double v, int limit)
{
	const long r = std::lround(v);
	return static_cast<unsigned>(r < 0 ? 0 : r > limit ? limit : r);
}

struct ApiRun {
	std::vector<std::vector<Detection>> detections;
	std::vector<double> ms;
};

// calped's C++ API on the recorded frames, configured as the element's properties say:
// model, calibration, resize 2, everything else the defaults.
ApiRun runDetector(const std::vector<FrameRecord> &frames, const CapsFormat &caps)
{
	ApiRun out;
	std::vector<uint8_t> blob;
	Model model;
	CameraModel camera;
	std::vector<uint8_t> text;
	if (!test::readFile(test::inriaModelBlob(), blob) || !test::readFile(calibrationPath(), text)) {
		ADD_FAILURE() << "cannot read the model or the calibration";
		return out;
	}
	EXPECT_TRUE(loadModel(blob.data(), blob.size(), model).ok());
	EXPECT_TRUE(loadCalibration(reinterpret_cast<const char *>(text.data()), text.size(), "View_001.xml",
				    camera).ok());
	DetectorConfig config;
	config.maxWidth = frames.at(0).width;
	config.maxHeight = frames.at(0).height;
	config.resize = 2;
	config.camera = &camera;
	std::unique_ptr<Detector> detector;
	const Status st = Detector::create(model, config, detector);
	if (!st.ok()) {
		ADD_FAILURE() << st.message();
		return out;
	}
	for (const FrameRecord &f : frames) {
		Detections dets;
		const Status s = detector->detect(viewOf(f, caps), dets);
		EXPECT_TRUE(s.ok()) << s.message();
		out.detections.emplace_back(dets.begin(), dets.end());
		out.ms.push_back(detector->lastStats().msTotal);
	}
	return out;
}

double mean(const std::vector<double> &v)
{
	double s = 0;
	for (double x : v)
		s += x;
	return v.empty() ? 0 : s / static_cast<double>(v.size());
}

void expectSameDetections(const CapsFormat &caps, int frames)
{
	const char *format = caps.caps;
	const PipelineRun run = runPipeline(videoPipeline(format, elementArgs()), frames);
	ASSERT_EQ(run.error, "");
	ASSERT_EQ(static_cast<int>(run.frames.size()), frames);
	const ApiRun api = runDetector(run.frames, caps);
	ASSERT_EQ(api.detections.size(), run.frames.size());
	size_t total = 0;
	for (size_t k = 0; k < run.frames.size(); k++) {
		const FrameRecord &f = run.frames[k];
		const std::vector<Detection> &want = api.detections[k];
		SCOPED_TRACE(std::string(format) + " frame " + std::to_string(k + 1));
		ASSERT_EQ(f.rois.size(), want.size());
		for (size_t i = 0; i < want.size(); i++) {
			const RoiRecord &r = f.rois[i];
			const Detection &d = want[i];
			EXPECT_EQ(r.type, "person");
			EXPECT_EQ(r.id, static_cast<int>(i));
			EXPECT_EQ(r.parentId, -1);
			const unsigned x0 = roundedEdge(d.x, f.width), y0 = roundedEdge(d.y, f.height);
			EXPECT_EQ(r.x, x0);
			EXPECT_EQ(r.y, y0);
			EXPECT_EQ(r.w, roundedEdge(static_cast<double>(d.x) + d.w, f.width) - x0);
			EXPECT_EQ(r.h, roundedEdge(static_cast<double>(d.y) + d.h, f.height) - y0);
			ASSERT_TRUE(r.hasParams);
			EXPECT_EQ(r.score, static_cast<double>(d.score)); // exactly
			EXPECT_EQ(r.hasGround, std::isfinite(d.groundX));
			if (r.hasGround) {
				EXPECT_EQ(r.groundX, static_cast<double>(d.groundX));
				EXPECT_EQ(r.groundY, static_cast<double>(d.groundY));
			}
			EXPECT_EQ(r.hasHeight, std::isfinite(d.worldHeight));
			if (r.hasHeight) {
				EXPECT_EQ(r.worldHeight, static_cast<double>(d.worldHeight));
			}
		}
		total += want.size();
	}
	EXPECT_GT(total, run.frames.size()) << "PETS frames have several people each";

	// One message per frame, in order, saying what the metas say.
	ASSERT_GE(run.messages.size(), run.frames.size());
	std::vector<double> msElement, msDetector;
	for (size_t k = 0; k < run.frames.size(); k++) {
		const MessageRecord &m = run.messages[k];
		EXPECT_EQ(m.frame, k + 1);
		EXPECT_EQ(m.pts, run.frames[k].pts);
		EXPECT_EQ(m.count, static_cast<int>(run.frames[k].rois.size()));
		EXPECT_EQ(m.method, "calibrated");
		EXPECT_GT(m.ms, 0);
		EXPECT_GE(m.msElement, m.ms);
		msElement.push_back(m.msElement);
		msDetector.push_back(m.ms);
	}
	std::printf("%s, %zu frames, %zu detections: element %.2f ms/frame (its detector %.2f), "
		    "calped::Detector on the same buffers %.2f ms/frame (FrameStats::msTotal)\n",
		    format, run.frames.size(), total, mean(msElement), mean(msDetector), mean(api.ms));
}

// Runs a pipeline that must fail; returns the error message ("" when none came).
std::string pipelineError(const std::string &description)
{
	const PipelineRun run = runPipeline(description + " ! appsink name=sink sync=false", 2);
	return run.error;
}

std::string writeTempFile(const char *name, const std::string &content)
{
	const std::string path = env("CALPED_BUILD_DIR") + "/tests/gstreamer/" + name;
	std::ofstream(path, std::ios::binary) << content;
	return path;
}

const char *kTestSource = "videotestsrc num-buffers=2 ! video/x-raw,format=RGB,width=320,height=240";

} // namespace

TEST(GstElement, InspectSeesTheElementAndItsProperties)
{
	if (sanitized())
		GTEST_SKIP() << "sanitizer build: gst-inspect-1.0 is not instrumented and cannot load the "
				"ASan-built plugin (the in-process cases cover it)";
	const ToolRun r = runTool({ "gst-inspect-1.0", "calped" });
	if (!r.found)
		GTEST_SKIP() << "no gst-inspect-1.0 (gstreamer1.0-tools)";
	ASSERT_EQ(r.exitStatus, 0) << r.err;
	for (const char *text : { "GstVideoFilter", "calped pedestrian detector", "NV12", "I420", "YUY2",
				  "GRAY8", "BGR", "model", "calibration", "method", "resize", "resize-at",
				  "levels", "reject-static", "min-score", "draw", "placed", "toolbox",
				  "generic", "calibrated", "pyramid", "frame" })
		EXPECT_NE(r.out.find(text), std::string::npos) << "gst-inspect-1.0 calped lacks " << text;
}

TEST(GstElement, LaunchRunsTheVideoToEos)
{
	if (sanitized())
		GTEST_SKIP() << "sanitizer build: gst-launch-1.0 is not instrumented and cannot load the "
				"ASan-built plugin (the in-process cases cover it)";
	REQUIRE_INPUTS(true);
	// Frames 1..300 of 795 (identity passes eos-after - 1 buffers, then ends the stream) keep
	// it well under a minute on a loaded machine.
	const ToolRun r = runTool({ "gst-launch-1.0", "-q", "filesrc", "location=" + videoPath(), "!",
				    "decodebin", "!", "videoconvert", "!", "video/x-raw,format=NV12", "!",
				    "identity", "eos-after=301", "!", "calped",
				    "model=" + test::inriaModelBlob(), "calibration=" + calibrationPath(),
				    "resize=2", "!", "fakesink" });
	if (!r.found)
		GTEST_SKIP() << "no gst-launch-1.0 (gstreamer1.0-tools)";
	EXPECT_EQ(r.exitStatus, 0) << r.out << r.err;
	EXPECT_EQ(r.err.find("ERROR"), std::string::npos) << r.err;
}

// Every caps format the element takes.
class GstElementFormat : public testing::TestWithParam<CapsFormat>
{};

TEST_P(GstElementFormat, MetasAreTheDetectorsDetections)
{
	REQUIRE_INPUTS(true);
	expectSameDetections(GetParam(), 20);
}

// Where drawBox writes the top-left pixel of a box, and what.
std::vector<uint8_t> boxCorner(const FrameRecord &f, const RoiRecord &r)
{
	const uint8_t *row = f.planes[0].data() + static_cast<size_t>(r.y) * f.strides[0];
	switch (f.format) {
	case GST_VIDEO_FORMAT_RGB:
	case GST_VIDEO_FORMAT_BGR:
		return { row + 3 * r.x, row + 3 * r.x + 3 };
	case GST_VIDEO_FORMAT_YUY2:
		return { row[2 * r.x] };
	default: // GRAY8, the luma planes of NV12 and I420
		return { row[r.x] };
	}
}

TEST_P(GstElementFormat, DrawingChangesOnlyTheFrame)
{
	REQUIRE_INPUTS(true);
	const PipelineRun plain = runPipeline(videoPipeline(GetParam().caps, elementArgs()), 3);
	const PipelineRun drawn = runPipeline(videoPipeline(GetParam().caps, elementArgs() + " draw=true"), 3);
	ASSERT_EQ(plain.error, "");
	ASSERT_EQ(drawn.error, "");
	ASSERT_EQ(plain.frames.size(), 3u);
	ASSERT_EQ(drawn.frames.size(), 3u);
	const bool colour = GetParam().format == PixelFormat::RGB8 || GetParam().format == PixelFormat::BGR8;
	const std::vector<uint8_t> pen = colour ? std::vector<uint8_t>{ 0, 255, 0 } : std::vector<uint8_t>{ 255 };
	for (size_t k = 0; k < 3; k++) {
		const FrameRecord &a = plain.frames[k], &b = drawn.frames[k];
		ASSERT_FALSE(a.rois.empty());
		ASSERT_EQ(a.rois.size(), b.rois.size());
		EXPECT_NE(a.planes[0], b.planes[0]) << "frame " << k + 1;
		for (size_t p = 1; p < a.planes.size(); p++)
			EXPECT_EQ(a.planes[p], b.planes[p]) << "chroma plane " << p << " changed";
		EXPECT_EQ(boxCorner(b, b.rois[0]), pen);
	}
}

INSTANTIATE_TEST_SUITE_P(Caps, GstElementFormat,
			 testing::Values(CapsFormat{ "RGB", PixelFormat::RGB8, false },
					 CapsFormat{ "BGR", PixelFormat::BGR8, false },
					 CapsFormat{ "GRAY8", PixelFormat::Gray8, false },
					 CapsFormat{ "NV12", PixelFormat::NV12, true },
					 CapsFormat{ "I420", PixelFormat::YUV420, true },
					 CapsFormat{ "YUY2", PixelFormat::YUYV, true }),
			 [](const testing::TestParamInfo<CapsFormat> &info) { return std::string(info.param.caps); });

// The element's per-frame path allocates nothing of its own: operator new is counted
// (tests/common/alloc_counter.cpp; the plugin's calls bind to it) while calped transforms
// frames 6..20. GStreamer, GLib and libav are C and allocate with malloc (their metas,
// structures and messages are theirs), and the test thread only waits for the end.
struct FrameCounts {
	int seen = 0;          // buffers arriving at calped's sink pad
	long allocations = -1; // while frames 6..20 were transformed
};

GstPadProbeReturn countFrames(GstPad *, GstPadProbeInfo *, gpointer data)
{
	FrameCounts &c = *static_cast<FrameCounts *>(data);
	c.seen++;
	if (c.seen == 6)
		test::startCountingAllocations();
	else if (c.seen == 21)
		c.allocations = test::stopCountingAllocations();
	return GST_PAD_PROBE_OK;
}

TEST(GstElement, NoAllocationPerFrame)
{
	REQUIRE_INPUTS(true);
	const std::string description = "filesrc location=" + videoPath() +
		" ! decodebin ! videoconvert ! video/x-raw,format=NV12 ! identity eos-after=23 ! calped name=det " +
		elementArgs() + " reject-static=true ! fakesink sync=false";
	GError *err = nullptr;
	GstElement *pipeline = gst_parse_launch(description.c_str(), &err);
	ASSERT_NE(pipeline, nullptr) << (err ? err->message : "?");
	FrameCounts counts;
	GstElement *det = gst_bin_get_by_name(GST_BIN(pipeline), "det");
	GstPad *pad = gst_element_get_static_pad(det, "sink");
	gst_pad_add_probe(pad, GST_PAD_PROBE_TYPE_BUFFER, countFrames, &counts, nullptr);
	GstBus *bus = gst_element_get_bus(pipeline);
	gst_element_set_state(pipeline, GST_STATE_PLAYING);
	GstMessage *msg = gst_bus_timed_pop_filtered(bus, 60 * GST_SECOND,
		static_cast<GstMessageType>(GST_MESSAGE_EOS | GST_MESSAGE_ERROR));
	ASSERT_NE(msg, nullptr);
	EXPECT_EQ(GST_MESSAGE_TYPE(msg), GST_MESSAGE_EOS);
	gst_message_unref(msg);
	gst_element_set_state(pipeline, GST_STATE_NULL);
	EXPECT_GE(counts.seen, 21);
	EXPECT_EQ(counts.allocations, 0) << "operator new calls while calped transformed frames 6-20";
	gst_object_unref(bus);
	gst_object_unref(pad);
	gst_object_unref(det);
	gst_object_unref(pipeline);
}

// Behind a tee every buffer is shared (not writable): the element still attaches its metas
// (GstBaseTransform gives it a shallow copy), the same as on an unshared buffer.
TEST(GstElement, SharedBuffersBehindATeeGetTheirMetas)
{
	REQUIRE_INPUTS(true);
	if (!haveElements({ "tee", "queue", "fakesink" }))
		GTEST_SKIP() << "no tee, queue or fakesink (gstreamer1.0-plugins-base)";
	const PipelineRun plain = runPipeline(videoPipeline("NV12", elementArgs()), 3);
	const PipelineRun shared = runPipeline(
		"filesrc location=" + videoPath() + " ! decodebin ! videoconvert ! video/x-raw,format=NV12 "
		"! tee name=t ! queue ! calped " + elementArgs() +
		" ! appsink name=sink sync=false max-buffers=4 t. ! queue ! fakesink sync=false", 3);
	ASSERT_EQ(shared.error, "");
	ASSERT_EQ(plain.frames.size(), 3u);
	ASSERT_EQ(shared.frames.size(), 3u);
	for (size_t k = 0; k < 3; k++) {
		ASSERT_FALSE(plain.frames[k].rois.empty());
		ASSERT_EQ(shared.frames[k].rois.size(), plain.frames[k].rois.size()) << "frame " << k + 1;
		for (size_t i = 0; i < plain.frames[k].rois.size(); i++)
			EXPECT_EQ(shared.frames[k].rois[i].score, plain.frames[k].rois[i].score);
	}
}

TEST(GstElement, MinScoreDropsWeakDetections)
{
	REQUIRE_INPUTS(true);
	const PipelineRun all = runPipeline(videoPipeline("NV12", elementArgs()), 3);
	ASSERT_EQ(all.frames.size(), 3u);
	ASSERT_FALSE(all.frames[0].rois.empty());
	double best = -1e300;
	for (const RoiRecord &r : all.frames[0].rois)
		best = std::max(best, r.score);
	char text[32];
	std::snprintf(text, sizeof text, "%.17g", best); // exactly the double again
	const PipelineRun strong = runPipeline(videoPipeline("NV12", elementArgs() + " min-score=" + text), 1);
	ASSERT_EQ(strong.frames.size(), 1u);
	ASSERT_EQ(strong.frames[0].rois.size(), 1u);
	EXPECT_EQ(strong.frames[0].rois[0].score, best);
}

#define REQUIRE_TEST_SOURCE()                                                              \
	do {                                                                               \
		if (!haveElements({ "videotestsrc", "appsink" }))                               \
			GTEST_SKIP() << "no videotestsrc or appsink (gstreamer1.0-plugins-base)"; \
	} while (0)

#define REQUIRE_MODEL()                                                                        \
	do {                                                                                   \
		if (test::inriaModelBlob().empty())                                                 \
			GTEST_SKIP() << "no INRIA model blob (needs ../shared and calped-convert)";    \
	} while (0)

// The error of `calped ARGS` on the test source; "model=BLOB" is prepended with `model`.
std::string testSourceError(const std::string &args, bool model = true)
{
	const std::string m = model ? "model=" + test::inriaModelBlob() + " " : "";
	return pipelineError(std::string(kTestSource) + " ! calped " + m + args);
}

TEST(GstElement, MissingModelIsAnElementErrorNamingTheFile)
{
	REQUIRE_TEST_SOURCE();
	const std::string err = testSourceError("model=/nonexistent/calped-model.cpm", false);
	EXPECT_NE(err.find("/nonexistent/calped-model.cpm"), std::string::npos) << err;
	EXPECT_NE(err.find("not found"), std::string::npos) << err;
}

TEST(GstElement, NoModelPropertyIsAnElementError)
{
	REQUIRE_TEST_SOURCE();
	const std::string err = testSourceError("", false);
	EXPECT_NE(err.find("'model' property"), std::string::npos) << err;
}

TEST(GstElement, CorruptModelIsAnElementErrorNamingTheProblem)
{
	REQUIRE_TEST_SOURCE();
	const std::string path = writeTempFile("corrupt.cpm", std::string(64, 'x'));
	const std::string err = testSourceError("model=" + path, false);
	EXPECT_NE(err.find(path), std::string::npos) << err;
	EXPECT_NE(err.find("ModelBadMagic"), std::string::npos) << err;
}

TEST(GstElement, CorruptCalibrationIsAnElementError)
{
	REQUIRE_TEST_SOURCE();
	REQUIRE_MODEL();
	const std::string path = writeTempFile("corrupt-calibration.xml", "<Camera name=\"x\"><Geometry");
	const std::string err = testSourceError("calibration=" + path);
	EXPECT_NE(err.find("calibration: "), std::string::npos) << err;
	EXPECT_NE(err.find(path), std::string::npos) << err;
}

TEST(GstElement, CalibrationForAnotherFrameSizeIsAClearError)
{
	REQUIRE_TEST_SOURCE();
	REQUIRE_INPUTS(false);
	const std::string err = testSourceError(elementArgs(), false);
	// The one check of the core (CameraModel::checkFrameSize), behind the calibration's name.
	EXPECT_NE(err.find("calibration "), std::string::npos) << err;
	EXPECT_NE(err.find("the calibration is for 768x576 images, the frames are 320x240"), std::string::npos) << err;
}

TEST(GstElement, DetectorSetupFailureIsAnElementErrorWithCalpedsMessage)
{
	REQUIRE_TEST_SOURCE();
	REQUIRE_MODEL();
	const std::string err = testSourceError("method=calibrated");
	EXPECT_NE(err.find("cannot set up the detector for 320x240 frames: InvalidArgument: "), std::string::npos)
		<< err;
	EXPECT_NE(err.find("camera"), std::string::npos) << err;
}

TEST(GstElement, AutoCalibrationCollectsWithTheGenericMethod)
{
	REQUIRE_TEST_SOURCE();
	REQUIRE_MODEL();
	// calibration=auto: the generic method while too few people have been seen (the test
	// source shows none), whatever the frames.
	const PipelineRun run = runPipeline(std::string(kTestSource) + " ! calped model=" +
					    test::inriaModelBlob() +
					    " calibration=auto ! appsink name=sink sync=false", 2);
	EXPECT_EQ(run.error, "");
	ASSERT_EQ(run.messages.size(), 2u);
	EXPECT_EQ(run.messages[0].method, "generic");
	// It runs the generic method first: asking for another is refused by name.
	const std::string err = testSourceError("calibration=auto method=calibrated");
	EXPECT_NE(err.find("calibration=auto runs the generic method"), std::string::npos) << err;
}

TEST(GstElement, GenericMethodWithoutCalibration)
{
	REQUIRE_TEST_SOURCE();
	REQUIRE_MODEL();
	const PipelineRun run = runPipeline(std::string(kTestSource) + " ! calped model=" +
					    test::inriaModelBlob() + " ! appsink name=sink sync=false", 2);
	EXPECT_EQ(run.error, "");
	ASSERT_EQ(run.messages.size(), 2u);
	EXPECT_EQ(run.messages[0].method, "generic");
	// Without a calibration the detection structures have no world fields.
	for (const FrameRecord &f : run.frames)
		for (const RoiRecord &r : f.rois)
			EXPECT_FALSE(r.hasGround || r.hasHeight);
}

// Sanitizer builds (the hooks are called by ASan and LeakSanitizer only): GLib allocates in
// the constructors of the libraries GStreamer's plugins load (decoders), and LeakSanitizer
// reports those blocks at exit; they are not calped's. Suppressed: allocations made while a
// library initialises (_dl_init), and GLib's quark table (interned strings live as long as
// the process by design; a fresh registry, as in CI, interns the names of every plugin it
// scans). The _dl_init frame is only seen with the slow unwinder (Debian's GLib has no
// frame pointers), hence fast_unwind_on_malloc=0.
extern "C" const char *__lsan_default_suppressions()
{
	return "leak:_dl_init\nleak:g_quark_from_string\nleak:g_quark_from_static_string\n";
}
extern "C" const char *__asan_default_options()
{
	return "fast_unwind_on_malloc=0";
}

int main(int argc, char **argv)
{
	gst_init(&argc, &argv);
	testing::InitGoogleTest(&argc, argv);
	const int rc = RUN_ALL_TESTS();
	gst_deinit();
	return rc;
}
