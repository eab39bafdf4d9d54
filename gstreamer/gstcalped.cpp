// SPDX-License-Identifier: BSD-2-Clause
// The `calped` element (docs/gstreamer.md). Life cycle:
//   start()     (READY -> PAUSED)  reads the model blob and the calibration file;
//   set_info()  (caps negotiated)  creates the Detector for the negotiated frame size;
//   transform_ip()                  one detect() per frame, metas, a bus message, drawing;
//   stop()      (PAUSED -> READY)  frees the detector, the model and the camera.
// Every failure is a GST_ELEMENT_ERROR carrying calped's message; nothing throws.
#include "gstcalped.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

#include <gst/video/gstvideometa.h>

#include <vector>

#include <calped/calibration.h>
#include <calped/detector.h>
#include <calped/model.h>
#include <calped/self_calibrating_detector.h>

#include "frame_publisher.h"
#include "json_frame.h"
#include "video_frame.h"

GST_DEBUG_CATEGORY_STATIC(gst_calped_debug);
#define GST_CAT_DEFAULT gst_calped_debug

namespace {

using namespace calped;

enum { PROP_0, PROP_MODEL, PROP_CALIBRATION, PROP_METHOD, PROP_RESIZE, PROP_RESIZE_AT,
       PROP_LEVELS, PROP_REJECT_STATIC, PROP_MIN_SCORE, PROP_DRAW, PROP_MQTT, PROP_CAMERA_ID,
       PROP_THREADS };

constexpr double kDefaultResize = 1.0;
constexpr double kDefaultMinScore = -G_MAXDOUBLE;

// What the properties hold; copied under the object lock where it is used.
struct Settings {
	std::string model, calibration;
	DetectionMethod method = DetectionMethod::Auto;
	double resize = kDefaultResize;
	ResizeAt resizeAt = ResizeAt::Pyramid;
	PyramidLevels levels = PyramidLevels::Placed;
	bool rejectStatic = false;
	int threads = 0; // DetectorConfig::threads; 0: recommendedThreads()
	double minScore = kDefaultMinScore;
	bool draw = false;
	std::string mqtt, cameraId; // mqtt://HOST[:PORT]/TOPIC (docs/mqtt.md); empty: none
};

// Everything made from the settings: from start() (model, camera) and set_info() (the
// detector) to stop().
struct Session {
	Model model;
	bool hasModel = false;
	CameraModel camera;
	bool hasCamera = false;
	bool calibAuto = false; // calibration=auto: selfCalibrating instead of detector
	std::unique_ptr<Detector> detector;
	std::unique_ptr<SelfCalibratingDetector> selfCalibrating;
	mqtt::FramePublisher publisher;
	std::vector<Detection> published; // the reported detections of a frame, for the message
	PixelFormat format = PixelFormat::RGB8;
	YuvEncoding yuv = YuvEncoding::Bt601Limited;
	const char *method = "";
	guint64 frames = 0;
	bool warnedTooSmall = false;
};

// Registers an enum type once (the GType is written once, by the first caller).
GType enumType(gsize &type, const char *name, const GEnumValue *values)
{
	if (g_once_init_enter(&type))
		g_once_init_leave(&type, g_enum_register_static(name, values));
	return type;
}

const GEnumValue kMethods[] = {
	{ gint(DetectionMethod::Auto), "calibrated with a calibration, else generic", "auto" },
	{ gint(DetectionMethod::Generic), "Dollar's sliding window over every window", "generic" },
	{ gint(DetectionMethod::Calibrated), "only where a person can stand (needs calibration)", "calibrated" },
	{ 0, nullptr, nullptr },
};
const GEnumValue kResizeAt[] = {
	{ gint(ResizeAt::Pyramid), "inside the feature pyramid (resize >= 1)", "pyramid" },
	{ gint(ResizeAt::Frame), "the frame is resampled first", "frame" },
	{ 0, nullptr, nullptr },
};
const GEnumValue kLevels[] = {
	{ gint(PyramidLevels::Placed), "computed levels placed for the camera (calibrated method)", "placed" },
	{ gint(PyramidLevels::Toolbox), "one computed level per octave, as Dollar's toolbox", "toolbox" },
	{ 0, nullptr, nullptr },
};
gsize methodType = 0, resizeAtType = 0, levelsType = 0;

GType methodEnumType() { return enumType(methodType, "GstCalpedMethod", kMethods); }
GType resizeAtEnumType() { return enumType(resizeAtType, "GstCalpedResizeAt", kResizeAt); }
GType levelsEnumType() { return enumType(levelsType, "GstCalpedLevels", kLevels); }

const char *methodName(DetectionMethod m)
{
	return m == DetectionMethod::Calibrated ? "calibrated" : "generic";
}

GQuark personQuark()
{
	static GQuark q = 0;
	if (!q)
		q = g_quark_from_static_string("person");
	return q;
}

} // namespace

struct _GstCalped {
	GstVideoFilter parent;
	Settings *settings; // guarded by the object lock
	Session *session;   // streaming thread (and start/stop, when it is not running)
};

G_DEFINE_TYPE(GstCalped, gst_calped, GST_TYPE_VIDEO_FILTER);
GST_ELEMENT_REGISTER_DEFINE(calped, "calped", GST_RANK_NONE, GST_TYPE_CALPED);

namespace {

Settings snapshot(GstCalped *self)
{
	GST_OBJECT_LOCK(self);
	Settings s = *self->settings;
	GST_OBJECT_UNLOCK(self);
	return s;
}

// Reads a whole file; on failure posts an element error naming `what` and the file.
bool readWholeFile(GstCalped *self, const char *what, const std::string &path, gchar *&data,
		   gsize &size)
{
	GError *err = nullptr;
	if (g_file_get_contents(path.c_str(), &data, &size, &err))
		return true;
	if (g_error_matches(err, G_FILE_ERROR, G_FILE_ERROR_NOENT))
		GST_ELEMENT_ERROR(self, RESOURCE, NOT_FOUND, ("%s file %s not found", what, path.c_str()),
				  ("%s", err->message));
	else
		GST_ELEMENT_ERROR(self, RESOURCE, OPEN_READ, ("cannot read %s file %s", what, path.c_str()),
				  ("%s", err->message));
	g_error_free(err);
	return false;
}

bool loadModelFile(GstCalped *self, const Settings &s, Session &session)
{
	if (s.model.empty()) {
		GST_ELEMENT_ERROR(self, RESOURCE, NOT_FOUND,
				  ("no model: set the 'model' property to a calped model blob (.cpm)"), (nullptr));
		return false;
	}
	gchar *data = nullptr;
	gsize size = 0;
	if (!readWholeFile(self, "model", s.model, data, size))
		return false;
	const Status st = loadModel(reinterpret_cast<const uint8_t *>(data), size, session.model);
	g_free(data);
	if (!st.ok()) {
		GST_ELEMENT_ERROR(self, RESOURCE, FAILED, ("model %s: %s", s.model.c_str(), st.message()),
				  (nullptr));
		return false;
	}
	session.hasModel = true;
	return true;
}

bool loadCalibrationFile(GstCalped *self, const Settings &s, Session &session)
{
	if (s.calibration.empty())
		return true;
	if (s.calibration == "auto") {
		if (s.method != DetectionMethod::Auto) {
			GST_ELEMENT_ERROR(self, RESOURCE, SETTINGS,
					  ("calibration=auto runs the generic method, then the calibrated one: "
					   "leave method at auto"),
					  (nullptr));
			return false;
		}
		session.calibAuto = true;
		return true;
	}
	gchar *data = nullptr;
	gsize size = 0;
	if (!readWholeFile(self, "calibration", s.calibration, data, size))
		return false;
	const Status st = loadCalibration(data, size, s.calibration.c_str(), session.camera);
	g_free(data);
	if (!st.ok()) {
		GST_ELEMENT_ERROR(self, RESOURCE, FAILED, ("calibration: %s", st.message()), (nullptr));
		return false;
	}
	session.hasCamera = true;
	return true;
}

DetectorConfig configFor(const Settings &s, Session &session, int width, int height)
{
	DetectorConfig c;
	c.maxWidth = width;
	c.maxHeight = height;
	c.resize = s.resize;
	c.resizeAt = s.resizeAt;
	c.method = s.method;
	c.threads = s.threads > 0 ? s.threads : recommendedThreads();
	if (session.hasCamera)
		c.camera = &session.camera;
	// Refused with the generic method: set only where the calibrated method runs.
	if (c.resolvedMethod() == DetectionMethod::Calibrated) {
		CalibratedSettings cal;
		cal.levels = s.levels;
		c.calibrated = cal;
	}
	if (s.rejectStatic)
		c.staticRejection = StaticRejection();
	return c;
}

gboolean calpedStart(GstBaseTransform *trans)
{
	GstCalped *self = GST_CALPED(trans);
	const Settings s = snapshot(self);
	delete self->session;
	self->session = new Session();
	if (!loadModelFile(self, s, *self->session) || !loadCalibrationFile(self, s, *self->session))
		return FALSE;
	if (!s.cameraId.empty() && s.mqtt.empty()) {
		GST_ELEMENT_ERROR(self, RESOURCE, SETTINGS, ("camera-id is for mqtt: set mqtt too"), (nullptr));
		return FALSE;
	}
	if (!s.mqtt.empty()) {
		// Connects now: an unreachable broker is an error at start, not a silent loss.
		mqtt::FramePublisherOptions options;
		options.url = s.mqtt;
		options.cameraId = s.cameraId;
		std::string error;
		if (!self->session->publisher.open(options, error)) {
			GST_ELEMENT_ERROR(self, RESOURCE, OPEN_WRITE, ("%s", error.c_str()), (nullptr));
			return FALSE;
		}
	}
	return TRUE;
}

gboolean calpedStop(GstBaseTransform *trans)
{
	GstCalped *self = GST_CALPED(trans);
	if (self->session && self->session->publisher.isOpen()) {
		self->session->publisher.close();
		GST_INFO_OBJECT(self, "%s", self->session->publisher.summary().c_str());
	}
	delete self->session;
	self->session = nullptr;
	return TRUE;
}

gboolean calpedSetInfo(GstVideoFilter *filter, GstCaps *, GstVideoInfo *in, GstCaps *, GstVideoInfo *)
{
	GstCalped *self = GST_CALPED(filter);
	Session *session = self->session;
	if (!session || !session->hasModel) {
		GST_ELEMENT_ERROR(self, CORE, STATE_CHANGE, ("caps before the model was loaded"), (nullptr));
		return FALSE;
	}
	session->detector.reset(); // a new size: a new detector (and a new static background)
	session->selfCalibrating.reset();
	if (!gst::pixelFormatFor(GST_VIDEO_INFO_FORMAT(in), session->format)) {
		GST_ELEMENT_ERROR(self, STREAM, FORMAT, ("unsupported format %s",
				  gst_video_format_to_string(GST_VIDEO_INFO_FORMAT(in))), (nullptr));
		return FALSE;
	}
	session->yuv = gst::yuvEncodingFor(in->colorimetry);
	const int width = GST_VIDEO_INFO_WIDTH(in), height = GST_VIDEO_INFO_HEIGHT(in);
	const Settings s = snapshot(self);
	if (session->hasCamera) {
		const Status fits = session->camera.checkFrameSize(width, height);
		if (!fits.ok()) {
			GST_ELEMENT_ERROR(self, STREAM, FORMAT, ("calibration %s: %s", s.calibration.c_str(), fits.message()),
					  ("scale the video to the calibration's size, or calibrate at this size"));
			return FALSE;
		}
	}
	const DetectorConfig config = configFor(s, *session, width, height);
	Status st;
	if (session->calibAuto) {
		SelfCalibratingConfig sc;
		sc.detector = config;
		sc.detector.method = DetectionMethod::Auto;
		CalibratedSettings cal;
		cal.levels = s.levels;
		sc.detector.calibrated = cal;
		st = SelfCalibratingDetector::create(session->model, sc, session->selfCalibrating);
	} else {
		st = Detector::create(session->model, config, session->detector);
	}
	if (!st.ok()) {
		GST_ELEMENT_ERROR(self, LIBRARY, SETTINGS,
				  ("cannot set up the detector for %dx%d frames: %s", width, height, st.message()),
				  (nullptr));
		return FALSE;
	}
	try {
		// Never more detections than candidates: publishing then allocates nothing per frame.
		session->published.reserve(size_t(config.maxCandidates));
	} catch (const std::bad_alloc &) {
		GST_ELEMENT_ERROR(self, RESOURCE, NO_SPACE_LEFT, ("out of memory"), (nullptr));
		return FALSE;
	}
	session->method = session->detector ? methodName(session->detector->config().resolvedMethod())
					    : methodName(DetectionMethod::Generic);
	GST_INFO_OBJECT(self, "detector for %dx%d %s frames, %s method", width, height,
			gst_video_format_to_string(GST_VIDEO_INFO_FORMAT(in)), session->method);
	return TRUE;
}

void addMeta(GstBuffer *buf, const Detection &d, const gst::PixelBox &box, guint id)
{
	GstVideoRegionOfInterestMeta *m = gst_buffer_add_video_region_of_interest_meta_id(
		buf, personQuark(), box.x, box.y, box.w, box.h);
	m->id = static_cast<gint>(id);
	m->parent_id = -1; // no parent
	GstStructure *s = gst_structure_new("detection", "score", G_TYPE_DOUBLE, static_cast<double>(d.score),
					    nullptr);
	// Present only when known (a calibration, the foot below the horizon): never NaN.
	if (std::isfinite(d.groundX) && std::isfinite(d.groundY))
		gst_structure_set(s, "ground-x", G_TYPE_DOUBLE, static_cast<double>(d.groundX), "ground-y",
				  G_TYPE_DOUBLE, static_cast<double>(d.groundY), nullptr);
	if (std::isfinite(d.worldHeight))
		gst_structure_set(s, "world-height", G_TYPE_DOUBLE, static_cast<double>(d.worldHeight), nullptr);
	gst_video_region_of_interest_meta_add_param(m, s);
}

void postFrameMessage(GstCalped *self, const Session &session, GstClockTime pts, int count,
		      double msDetector, double msElement)
{
	GstStructure *s = gst_structure_new("calped-detections",
		"frame", G_TYPE_UINT64, session.frames,
		"pts", G_TYPE_UINT64, static_cast<guint64>(pts),
		"count", G_TYPE_INT, count,
		"method", G_TYPE_STRING, session.method,
		"ms", G_TYPE_DOUBLE, msDetector,
		"ms-element", G_TYPE_DOUBLE, msElement, nullptr);
	// calibration=auto: the camera estimate in use (0 while collecting).
	if (session.selfCalibrating)
		gst_structure_set(s, "camera-estimate", G_TYPE_INT, session.selfCalibrating->cameraEstimate(),
				  nullptr);
	gst_element_post_message(GST_ELEMENT(self), gst_message_new_element(GST_OBJECT(self), s));
}

// Replaces GstVideoFilter's transform_ip, which maps every frame for writing: without
// drawing the pixels are only read, so a buffer whose memory is shared is never copied.
GstFlowReturn calpedTransformIp(GstBaseTransform *trans, GstBuffer *buf)
{
	const auto t0 = std::chrono::steady_clock::now();
	GstCalped *self = GST_CALPED(trans);
	GstVideoFilter *filter = GST_VIDEO_FILTER(trans);
	Session *session = self->session;
	if (!filter->negotiated || !session || (!session->detector && !session->selfCalibrating)) {
		GST_ELEMENT_ERROR(self, CORE, NOT_IMPLEMENTED, ("a buffer before the caps"), (nullptr));
		return GST_FLOW_NOT_NEGOTIATED;
	}
	GST_OBJECT_LOCK(self);
	const bool draw = self->settings->draw;
	const double minScore = self->settings->minScore;
	GST_OBJECT_UNLOCK(self);

	GstVideoFrame frame;
	// NO_REF: a mapped frame holding a reference would make the buffer read-only for metas.
	const int flags = GST_MAP_READ | GST_VIDEO_FRAME_MAP_FLAG_NO_REF | (draw ? GST_MAP_WRITE : 0);
	if (!gst_video_frame_map(&frame, &filter->in_info, buf, static_cast<GstMapFlags>(flags))) {
		GST_ELEMENT_ERROR(self, STREAM, FAILED, ("cannot map a video buffer"), (nullptr));
		return GST_FLOW_ERROR;
	}
	session->frames++;
	Detections dets;
	const ImageView view = gst::imageViewOf(frame, session->format, session->yuv);
	const Status st = session->detector ? session->detector->detect(view, dets)
					    : session->selfCalibrating->detect(view, dets);
	if (session->selfCalibrating)
		session->method = methodName(session->selfCalibrating->lastMethod());
	double msDetector = 0;
	if (st.code() == ErrorCode::ImageTooSmall) {
		if (!session->warnedTooSmall)
			GST_ELEMENT_WARNING(self, STREAM, FORMAT, ("frames too small for the model: no detections"),
					    ("%s", st.message()));
		session->warnedTooSmall = true;
		dets = Detections();
	} else if (!st.ok()) {
		gst_video_frame_unmap(&frame);
		GST_ELEMENT_ERROR(self, STREAM, FAILED, ("detection failed: %s", st.message()), (nullptr));
		return GST_FLOW_ERROR;
	} else {
		msDetector = session->detector ? session->detector->lastStats().msTotal
					       : session->selfCalibrating->lastStats().msTotal;
	}

	const int width = GST_VIDEO_FRAME_WIDTH(&frame), height = GST_VIDEO_FRAME_HEIGHT(&frame);
	guint count = 0;
	session->published.clear();
	for (const Detection &d : dets) {
		if (d.score < minScore)
			continue;
		const gst::PixelBox box = gst::pixelBoxOf(d, width, height);
		addMeta(buf, d, box, count++);
		if (draw)
			gst::drawBox(frame, box);
		if (session->publisher.isOpen())
			session->published.push_back(d);
	}
	gst_video_frame_unmap(&frame);
	if (session->publisher.isOpen()) {
		apps::JsonFrame record;
		record.frame = static_cast<long long>(session->frames);
		record.method = session->method;
		record.cameraEstimate = session->selfCalibrating ? session->selfCalibrating->cameraEstimate() : -1;
		record.width = width;
		record.height = height;
		record.ms = msDetector;
		if (GST_BUFFER_PTS_IS_VALID(buf))
			record.timestampNs = static_cast<int64_t>(GST_BUFFER_PTS(buf));
		Detections reported;
		reported.items = session->published.data();
		reported.count = static_cast<int>(session->published.size());
		// Never blocks: a full queue drops the message and counts it (docs/mqtt.md).
		session->publisher.publish(record, reported);
	}
	const double msElement =
		std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	postFrameMessage(self, *session, GST_BUFFER_PTS(buf), static_cast<int>(count), msDetector, msElement);
	return GST_FLOW_OK;
}

void calpedSetProperty(GObject *object, guint id, const GValue *value, GParamSpec *pspec)
{
	GstCalped *self = GST_CALPED(object);
	GST_OBJECT_LOCK(self);
	Settings &s = *self->settings;
	switch (id) {
	case PROP_MODEL:
		s.model = g_value_get_string(value) ? g_value_get_string(value) : "";
		break;
	case PROP_CALIBRATION:
		s.calibration = g_value_get_string(value) ? g_value_get_string(value) : "";
		break;
	case PROP_METHOD:
		s.method = static_cast<DetectionMethod>(g_value_get_enum(value));
		break;
	case PROP_RESIZE:
		s.resize = g_value_get_double(value);
		break;
	case PROP_RESIZE_AT:
		s.resizeAt = static_cast<ResizeAt>(g_value_get_enum(value));
		break;
	case PROP_LEVELS:
		s.levels = static_cast<PyramidLevels>(g_value_get_enum(value));
		break;
	case PROP_REJECT_STATIC:
		s.rejectStatic = g_value_get_boolean(value);
		break;
	case PROP_THREADS:
		s.threads = g_value_get_int(value);
		break;
	case PROP_MIN_SCORE:
		s.minScore = g_value_get_double(value);
		break;
	case PROP_DRAW:
		s.draw = g_value_get_boolean(value);
		break;
	case PROP_MQTT:
		s.mqtt = g_value_get_string(value) ? g_value_get_string(value) : "";
		break;
	case PROP_CAMERA_ID:
		s.cameraId = g_value_get_string(value) ? g_value_get_string(value) : "";
		break;
	default:
		G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, pspec);
		break;
	}
	GST_OBJECT_UNLOCK(self);
}

void calpedGetProperty(GObject *object, guint id, GValue *value, GParamSpec *pspec)
{
	GstCalped *self = GST_CALPED(object);
	GST_OBJECT_LOCK(self);
	const Settings &s = *self->settings;
	switch (id) {
	case PROP_MODEL:
		g_value_set_string(value, s.model.empty() ? nullptr : s.model.c_str());
		break;
	case PROP_CALIBRATION:
		g_value_set_string(value, s.calibration.empty() ? nullptr : s.calibration.c_str());
		break;
	case PROP_METHOD:
		g_value_set_enum(value, static_cast<gint>(s.method));
		break;
	case PROP_RESIZE:
		g_value_set_double(value, s.resize);
		break;
	case PROP_RESIZE_AT:
		g_value_set_enum(value, static_cast<gint>(s.resizeAt));
		break;
	case PROP_LEVELS:
		g_value_set_enum(value, static_cast<gint>(s.levels));
		break;
	case PROP_REJECT_STATIC:
		g_value_set_boolean(value, s.rejectStatic);
		break;
	case PROP_THREADS:
		g_value_set_int(value, s.threads);
		break;
	case PROP_MIN_SCORE:
		g_value_set_double(value, s.minScore);
		break;
	case PROP_DRAW:
		g_value_set_boolean(value, s.draw);
		break;
	case PROP_MQTT:
		g_value_set_string(value, s.mqtt.empty() ? nullptr : s.mqtt.c_str());
		break;
	case PROP_CAMERA_ID:
		g_value_set_string(value, s.cameraId.empty() ? nullptr : s.cameraId.c_str());
		break;
	default:
		G_OBJECT_WARN_INVALID_PROPERTY_ID(object, id, pspec);
		break;
	}
	GST_OBJECT_UNLOCK(self);
}

void calpedFinalize(GObject *object)
{
	GstCalped *self = GST_CALPED(object);
	delete self->session;
	delete self->settings;
	G_OBJECT_CLASS(gst_calped_parent_class)->finalize(object);
}

constexpr GParamFlags kReady =
	static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS | GST_PARAM_MUTABLE_READY);
constexpr GParamFlags kPlaying =
	static_cast<GParamFlags>(G_PARAM_READWRITE | G_PARAM_STATIC_STRINGS | GST_PARAM_MUTABLE_PLAYING);

} // namespace

static void gst_calped_class_init(GstCalpedClass *klass)
{
	GObjectClass *gobject = G_OBJECT_CLASS(klass);
	GstElementClass *element = GST_ELEMENT_CLASS(klass);
	GstBaseTransformClass *trans = GST_BASE_TRANSFORM_CLASS(klass);
	GstVideoFilterClass *filter = GST_VIDEO_FILTER_CLASS(klass);

	GST_DEBUG_CATEGORY_INIT(gst_calped_debug, "calped", 0, "calped pedestrian detector");

	gobject->set_property = calpedSetProperty;
	gobject->get_property = calpedGetProperty;
	gobject->finalize = calpedFinalize;

	g_object_class_install_property(gobject, PROP_MODEL,
		g_param_spec_string("model", "Model", "calped model blob (.cpm, from calped-convert); required",
				    nullptr, kReady));
	g_object_class_install_property(gobject, PROP_CALIBRATION,
		g_param_spec_string("calibration", "Calibration",
				    "camera calibration file (Tsai XML, OpenCV YAML, Town Centre .ci, projection "
				    "matrix); gives ground positions and world heights and enables the calibrated "
				    "method; 'auto': estimated from the people found (the generic method runs "
				    "until then, at the resize property; docs/calibration.md)",
				    nullptr, kReady));
	g_object_class_install_property(gobject, PROP_METHOD,
		g_param_spec_enum("method", "Method", "detection method", methodEnumType(),
				  static_cast<gint>(DetectionMethod::Auto), kReady));
	g_object_class_install_property(gobject, PROP_RESIZE,
		g_param_spec_double("resize", "Resize",
				    "detect as if the frame were scaled by this factor (the INRIA model finds "
				    "100-pixel people: PETS needs 2); boxes stay in frame pixels",
				    0.05, 8.0, kDefaultResize, kReady));
	g_object_class_install_property(gobject, PROP_RESIZE_AT,
		g_param_spec_enum("resize-at", "Resize at", "where the resize happens", resizeAtEnumType(),
				  static_cast<gint>(ResizeAt::Pyramid), kReady));
	g_object_class_install_property(gobject, PROP_LEVELS,
		g_param_spec_enum("levels", "Pyramid levels",
				  "which pyramid levels are computed (the calibrated method; ignored by the generic one)",
				  levelsEnumType(), static_cast<gint>(PyramidLevels::Placed), kReady));
	g_object_class_install_property(gobject, PROP_REJECT_STATIC,
		g_param_spec_boolean("reject-static", "Reject static",
				     "fixed camera: drop detections on static scene structure (after 50 frames)",
				     FALSE, kReady));
	g_object_class_install_property(gobject, PROP_THREADS,
		g_param_spec_int("threads", "Threads",
				 "threads the detector works on, the streaming thread included "
				 "(0: the online cores, at most 4; the detections do not depend on it)",
				 0, 64, 0, kReady));
	g_object_class_install_property(gobject, PROP_MIN_SCORE,
		g_param_spec_double("min-score", "Minimum score",
				    "report only detections scoring at least this (default: all)",
				    -G_MAXDOUBLE, G_MAXDOUBLE, kDefaultMinScore, kPlaying));
	g_object_class_install_property(gobject, PROP_DRAW,
		g_param_spec_boolean("draw", "Draw",
				     "draw the boxes into the frame (RGB, BGR, GRAY8; the luma of YUV formats)",
				     FALSE, kPlaying));

	g_object_class_install_property(gobject, PROP_MQTT,
		g_param_spec_string("mqtt", "MQTT",
				    "publish each frame's detections as one JSON message (QoS 1) to "
				    "mqtt://HOST[:PORT]/TOPIC (docs/mqtt.md); the broker must be reachable at start",
				    nullptr, kReady));
	g_object_class_install_property(gobject, PROP_CAMERA_ID,
		g_param_spec_string("camera-id", "Camera id",
				    "the camera's id in MQTT messages (default: the host name)", nullptr, kReady));

	GstCaps *caps = gst_caps_from_string(GST_VIDEO_CAPS_MAKE(CALPED_GST_FORMATS));
	gst_element_class_add_pad_template(element, gst_pad_template_new("sink", GST_PAD_SINK, GST_PAD_ALWAYS, caps));
	gst_element_class_add_pad_template(element, gst_pad_template_new("src", GST_PAD_SRC, GST_PAD_ALWAYS, caps));
	gst_caps_unref(caps);
	gst_element_class_set_static_metadata(element, "calped pedestrian detector", "Filter/Analyzer/Video",
		"Finds pedestrians (ACF detector, calibrated or generic method) and attaches a "
		"GstVideoRegionOfInterestMeta per detection",
		"calped project");

	trans->start = calpedStart;
	trans->stop = calpedStop;
	trans->transform_ip = calpedTransformIp;
	trans->passthrough_on_same_caps = FALSE;
	filter->set_info = calpedSetInfo;

	gst_type_mark_as_plugin_api(methodEnumType(), static_cast<GstPluginAPIFlags>(0));
	gst_type_mark_as_plugin_api(resizeAtEnumType(), static_cast<GstPluginAPIFlags>(0));
	gst_type_mark_as_plugin_api(levelsEnumType(), static_cast<GstPluginAPIFlags>(0));
}

static void gst_calped_init(GstCalped *self)
{
	self->settings = new Settings();
	self->session = nullptr;
	// In place, never passthrough: metas need a writable buffer, which GstBaseTransform
	// guarantees only outside passthrough (a shallow copy when the buffer is shared; the
	// pixels are copied only when drawing into shared memory).
	gst_base_transform_set_in_place(GST_BASE_TRANSFORM(self), TRUE);
	gst_base_transform_set_passthrough(GST_BASE_TRANSFORM(self), FALSE);
}
