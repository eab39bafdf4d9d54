// SPDX-License-Identifier: BSD-2-Clause
// The Aravis port against Debian's GigE Vision camera simulator on loopback (started by
// each test on its own 127.0.0.x address) and Aravis's in-process Fake device. Tests that
// need arv-fake-gv-camera-0.8 skip with a message when aravis-tools is absent.
#include <gtest/gtest.h>

#include <arv.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <calped/calped.h>

#include "common/alloc_counter.h"
#include "aravis_source.h"
#include "fake_gv_camera.h"
#include "file_source.h"
#include "frame_numbers.h"
#include "gvcp_probe.h"
#include "pixel_formats.h"
#include "test_data.h"

using namespace calped;
using namespace calped::ports;
using calped::test::FakeGvCamera;
using Clock = std::chrono::steady_clock;

namespace {

#define START_FAKE_CAMERA(camera, address, lost)                                   \
	do {                                                                       \
		if (calped::test::fakeGvCameraPath().empty())                      \
			GTEST_SKIP() << "aravis-tools is not installed (no "        \
					"arv-fake-gv-camera-0.8 on PATH): skipping"; \
		std::string why_;                                                  \
		ASSERT_TRUE((camera).start((address), (lost), why_)) << why_;      \
	} while (0)

Status openCamera(const std::string &address, const char *format, AravisOptions options,
		  std::unique_ptr<AravisSource> &out)
{
	options.camera = address;
	options.pixelFormat = format;
	return AravisSource::open(options, out);
}

// The simulator's Mono8 test image is a diagonal ramp, (x + y + k) mod 255 for a
// per-frame k: any packet of another frame (or a hole) breaks it.
bool isIntactRamp(const ImageView &im)
{
	const uint8_t k = im.planes[0][0];
	for (int y = 0; y < im.height; y++) {
		const uint8_t *row = im.planes[0] + static_cast<size_t>(y) * im.strides[0];
		for (int x = 0; x < im.width; x++)
			if (row[x] != static_cast<uint8_t>((k + x + y) % 255))
				return false;
	}
	return true;
}

std::unique_ptr<Detector> makeDetector(int width, int height)
{
	const std::string blob = calped::test::inriaModelBlob();
	if (blob.empty())
		return nullptr;
	std::vector<uint8_t> bytes;
	Model model;
	if (!calped::test::readFile(blob, bytes) || !loadModel(bytes.data(), bytes.size(), model).ok())
		return nullptr;
	DetectorConfig config;
	config.maxWidth = width;
	config.maxHeight = height;
	std::unique_ptr<Detector> det;
	if (!Detector::create(model, config, det).ok())
		return nullptr;
	return det;
}

} // namespace

// --- Pixel formats (no camera) ---

TEST(AravisPixelFormats, CameraFormatsMapWithoutConversion)
{
	PixelFormat f;
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_MONO_8, f));
	EXPECT_EQ(f, PixelFormat::Gray8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_RGB_8_PACKED, f));
	EXPECT_EQ(f, PixelFormat::RGB8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_BGR_8_PACKED, f));
	EXPECT_EQ(f, PixelFormat::BGR8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_YUV_422_YUYV_PACKED, f));
	EXPECT_EQ(f, PixelFormat::YUYV);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_BAYER_RG_8, f));
	EXPECT_EQ(f, PixelFormat::BayerRGGB8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_BAYER_GR_8, f));
	EXPECT_EQ(f, PixelFormat::BayerGRBG8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_BAYER_GB_8, f));
	EXPECT_EQ(f, PixelFormat::BayerGBRG8);
	ASSERT_TRUE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_BAYER_BG_8, f));
	EXPECT_EQ(f, PixelFormat::BayerBGGR8);
	// U Y V Y byte order is not YUYV; 16-bit formats need a conversion.
	EXPECT_FALSE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_YUV_422_PACKED, f));
	EXPECT_FALSE(pixelFormatFromPfnc(ARV_PIXEL_FORMAT_MONO_16, f));
}

TEST(AravisPixelFormats, ViewHonoursPaddingAndRefusesShortBuffers)
{
	// 3 rows of 15 bytes, each but the last followed by 2 bytes of padding.
	std::vector<uint8_t> data(17 * 2 + 15, 0);
	ImageView v;
	ASSERT_TRUE(viewReceivedImage(PixelFormat::RGB8, data.data(), data.size(), 5, 3, 2, v));
	EXPECT_EQ(v.strides[0], 17);
	EXPECT_EQ(v.planes[0], data.data());
	EXPECT_FALSE(viewReceivedImage(PixelFormat::RGB8, data.data(), data.size() - 1, 5, 3, 2, v));
	EXPECT_FALSE(viewReceivedImage(PixelFormat::RGB8, nullptr, data.size(), 5, 3, 0, v));
	EXPECT_FALSE(viewReceivedImage(PixelFormat::NV12, data.data(), data.size(), 5, 3, 0, v));
	ASSERT_TRUE(viewReceivedImage(PixelFormat::YUYV, data.data(), data.size(), 5, 3, 0, v));
	EXPECT_EQ(v.strides[0], 12); // 3 pairs of 4 bytes
}

// A leader's sides and padding are network data: beyond kMaxCameraSide / kMaxRowPadding
// they are refused before any int arithmetic (fuzz target aravis: 3 x INT_MAX overflowed
// the row size; padding 2^31 - 8 wrapped the int stride negative; tests/fuzz/regressions/aravis/).
TEST(AravisPixelFormats, ViewRefusesSidesAndPaddingBeyondTheirLimits)
{
	std::vector<uint8_t> data(1 << 16, 0);
	ImageView v;
	EXPECT_FALSE(viewReceivedImage(PixelFormat::RGB8, data.data(), data.size(), INT32_MAX, 1, 0, v));
	EXPECT_FALSE(viewReceivedImage(PixelFormat::Gray8, data.data(), data.size(), 8, 1, INT32_MAX - 7, v));
	EXPECT_FALSE(viewReceivedImage(PixelFormat::Gray8, data.data(), data.size(), 8, 1, kMaxRowPadding + 1, v));
	EXPECT_FALSE(viewReceivedImage(PixelFormat::Gray8, data.data(), data.size(), 1, kMaxCameraSide + 1, 0, v));
	ASSERT_TRUE(viewReceivedImage(PixelFormat::Gray8, data.data(), data.size(), 8, 1, kMaxRowPadding, v));
	EXPECT_EQ(v.strides[0], 8 + kMaxRowPadding);
}

// The stream the camera announces is checked before a buffer is sized from it.
TEST(AravisStreamPlan, InconsistentAnswersAreRefusedBeforeAllocating)
{
	StreamPlan plan;
	AnnouncedStream a;
	a.pfnc = ARV_PIXEL_FORMAT_RGB_8_PACKED;
	a.width = 640;
	a.height = 480;
	a.payload = 640 * 480 * 3;
	ASSERT_TRUE(planStream(a, "RGB8", plan).ok());
	EXPECT_EQ(plan.format, PixelFormat::RGB8);
	EXPECT_EQ(plan.payload, size_t(640 * 480 * 3));
	a.payload = 640 * 480 * 3 + 4096; // chunk data after the image
	EXPECT_TRUE(planStream(a, "RGB8", plan).ok());

	a.payload = 640 * 480; // a Mono8 payload for an RGB8 image
	Status st = planStream(a, "RGB8", plan);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "payload of 307200 bytes does not fit a 640x480 RGB8 image of 921600"),
		  nullptr) << st.message();
	a.payload = int64_t(1) << 32; // 4 GiB per buffer
	EXPECT_EQ(planStream(a, "RGB8", plan).code(), ErrorCode::CameraError);
	a.payload = 921600;
	a.height = 0;
	EXPECT_NE(std::strstr(planStream(a, "RGB8", plan).message(), "region is 640x0"), nullptr);
	a.height = -480;
	EXPECT_FALSE(planStream(a, "RGB8", plan).ok());
	a.height = 480;
	a.width = kMaxCameraSide + 1;
	EXPECT_FALSE(planStream(a, "RGB8", plan).ok());

	// A format calped cannot lend; the camera's name for it is outside text.
	a.width = 640;
	a.pfnc = ARV_PIXEL_FORMAT_MONO_16;
	st = planStream(a, "Mono16\x1b[31m\xff\n", plan);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "pixel format Mono16?[31m?? (0x01100007)"), nullptr)
		<< st.message();
}

// The liveness probe's reply: only the acknowledge of its own READREG, with the value.
TEST(AravisGvcpProbe, AnswerIsTheAcknowledgeOfTheProbesRead)
{
	uint8_t ack[12] = { 0x80, 0x04, 0x00, 0x81, 0x00, 0x04, 0x7e, 0x57, 0, 1, 0, 2 };
	EXPECT_TRUE(isProbeAnswer(ack, sizeof(ack))); // a busy status still answers
	EXPECT_FALSE(isProbeAnswer(ack, 8));           // the header without the register
	ack[7] = 0x58;                                 // another request's acknowledge
	EXPECT_FALSE(isProbeAnswer(ack, sizeof(ack)));
	ack[7] = 0x57;
	ack[3] = 0x83; // WRITEREG_ACK
	EXPECT_FALSE(isProbeAnswer(ack, sizeof(ack)));
}

// --- Frame numbers (no camera) ---

// GigE Vision 1.x block ids skip 0: 65535 is followed by 1. Aravis's simulators start at
// 65401, so every stream of more than 135 frames crosses this.
TEST(AravisFrameNumbers, GrowAcrossTheSixteenBitWrap)
{
	FrameNumbers n;
	EXPECT_EQ(n.next(65533), 65533u); // the first number is the camera's id
	EXPECT_EQ(n.next(65534), 65534u);
	EXPECT_EQ(n.next(65535), 65535u);
	EXPECT_EQ(n.next(1), 65536u);
	EXPECT_EQ(n.next(2), 65537u);
	EXPECT_EQ(n.unseen(), 0u) << "the skipped id 0 is not a frame";
}

TEST(AravisFrameNumbers, GapsAreUnseenFramesAlsoAcrossTheWrap)
{
	FrameNumbers n;
	EXPECT_EQ(n.next(65530), 65530u);
	EXPECT_EQ(n.next(65534), 65534u); // 65531..65533 never came out
	EXPECT_EQ(n.unseen(), 3u);
	EXPECT_EQ(n.next(3), 65538u); // 65535, 1, 2 never came out
	EXPECT_EQ(n.unseen(), 6u);
}

// A long stream from a 16-bit camera with some frames missing: the numbers count the
// camera's frames exactly, and the gaps exactly the missing ones.
TEST(AravisFrameNumbers, CountEveryFrameOfALongWrappingStream)
{
	FrameNumbers n;
	const uint64_t first = 65401;
	uint64_t missing = 0, lastNumber = 0;
	bool strictlyIncreasing = true, exact = true;
	for (uint64_t k = first; k < first + 300000; k++) {
		if (k % 97 == 0 || k % 1000 < 3) { // never came out of Aravis
			missing++;
			continue;
		}
		const uint64_t blockId = (k - 1) % 65535 + 1; // 1..65535
		const uint64_t number = n.next(blockId);
		strictlyIncreasing = strictlyIncreasing && number > lastNumber;
		exact = exact && number == k;
		lastNumber = number;
	}
	EXPECT_TRUE(strictlyIncreasing);
	EXPECT_TRUE(exact);
	EXPECT_EQ(n.unseen(), missing);
}

TEST(AravisFrameNumbers, SixtyFourBitIdsAreTakenAsTheyAre)
{
	FrameNumbers n;
	EXPECT_EQ(n.next(0), 0u); // USB3 Vision counts from 0
	EXPECT_EQ(n.next(1), 1u);
	EXPECT_EQ(n.next(5), 5u);
	EXPECT_EQ(n.unseen(), 3u);
	FrameNumbers m;
	EXPECT_EQ(m.next(65534), 65534u);
	EXPECT_EQ(m.next(65536), 65536u); // past 16 bits: 65535 never came out
	EXPECT_EQ(m.next(70000), 70000u);
	EXPECT_EQ(m.unseen(), 1u + 4463u);
}

// A camera whose counter goes back (it restarted it, or sends 0 after 65535): the numbers
// go on by one, and no gap is made up.
TEST(AravisFrameNumbers, ACounterThatGoesBackStillGivesGrowingNumbers)
{
	FrameNumbers n;
	EXPECT_EQ(n.next(5000), 5000u);
	EXPECT_EQ(n.next(5001), 5001u);
	EXPECT_EQ(n.next(1), 5002u);
	EXPECT_EQ(n.next(2), 5003u);
	EXPECT_EQ(n.next(65535), 5004u); // 2 -> 65535 is 2 steps back on the circle
	EXPECT_EQ(n.next(0), 5005u);
	EXPECT_EQ(n.next(1), 5006u);
	EXPECT_EQ(n.unseen(), 0u);
}

// After a reconnection the camera counts afresh (the simulator from 65401 again): the
// numbers continue, so the lent ids still only grow.
TEST(AravisFrameNumbers, AReconnectionContinuesTheNumbers)
{
	FrameNumbers n;
	n.restart(); // the first connection
	EXPECT_EQ(n.next(65401), 65401u);
	EXPECT_EQ(n.next(65420), 65420u);
	n.restart();
	EXPECT_EQ(n.next(65401), 65421u);
	EXPECT_EQ(n.next(65403), 65423u);
	EXPECT_EQ(n.unseen(), 18u + 1u) << "the gap across the reconnection is unknown, not counted";
}

// With arrival times, the frames a camera made while the connection was away are
// estimated from the time away and the frame interval seen before (issue 19: ~90 frames
// vanished uncounted across --reconnect).
TEST(AravisFrameNumbers, FramesLostAcrossAReconnectionAreEstimatedFromTimestamps)
{
	FrameNumbers n;
	constexpr int64_t kMs = 1000000, kInterval = 40 * kMs; // 25 frames per second
	int64_t t = 1000 * kMs;
	for (uint64_t id = 100; id < 110; id++, t += kInterval)
		n.next(id, t);
	EXPECT_EQ(n.unseen(), 0u);
	const uint64_t before = n.next(110, t); // the last frame before the loss
	n.restart();
	// 3.6 s away: 90 frame times, so 89 frames the camera made were never received.
	t += 90 * kInterval + 7 * kMs; // a little jitter
	EXPECT_EQ(n.next(1, t), before + 90);
	EXPECT_EQ(n.lostAcrossRestarts(), 89u);
	EXPECT_EQ(n.unseen(), 89u);
	// Then the ids step as usual.
	EXPECT_EQ(n.next(2, t + kInterval), before + 91);
	EXPECT_EQ(n.unseen(), 89u);
	// Without timestamps nothing is estimated (the older behaviour).
	FrameNumbers m;
	m.next(5);
	m.next(6);
	m.restart();
	m.next(1);
	EXPECT_EQ(m.lostAcrossRestarts(), 0u);
}

TEST(AravisSource, UnknownCameraIsCameraNotFound)
{
	std::unique_ptr<AravisSource> src;
	const Status st = openCamera("calped-no-such-camera", "", AravisOptions(), src);
	EXPECT_EQ(st.code(), ErrorCode::CameraNotFound) << st.message();
	EXPECT_NE(std::strstr(st.message(), "calped-no-such-camera"), nullptr) << st.message();
	EXPECT_FALSE(src);
}

TEST(AravisSource, RefusedSettingsAreCameraErrors)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	Status st = openCamera("127.0.0.1", "NoSuchFormat", AravisOptions(), src);
	EXPECT_EQ(st.code(), ErrorCode::CameraError) << st.message();
	EXPECT_NE(std::strstr(st.message(), "NoSuchFormat"), nullptr) << st.message();
	// A format the camera has but calped cannot lend without conversion.
	st = openCamera("127.0.0.1", "Mono16", AravisOptions(), src);
	EXPECT_EQ(st.code(), ErrorCode::CameraError) << st.message();
	EXPECT_NE(std::strstr(st.message(), "Mono16"), nullptr) << st.message();
	// The refused setting did not stick: the next run with the camera's own format
	// opens, and in the format the camera had before (issue 19).
	st = openCamera("127.0.0.1", "", AravisOptions(), src);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_NE(src->pixelFormatName(), "Mono16");
	src.reset();
	AravisOptions bad;
	bad.buffers = 1;
	EXPECT_EQ(openCamera("127.0.0.1", "", bad, src).code(), ErrorCode::InvalidArgument);
}

// --- Streaming from the GigE Vision simulator ---

// 100 frames through the detector with the default (clean) settings: packet socket off,
// socket buffer sized to the payload, resend on. Nothing incomplete, no timeout, and no
// allocation per frame in the port or the detector.
TEST(AravisSource, StreamsHundredFramesCleanlyThroughTheDetector)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	Status st = openCamera("127.0.0.1", "RGB8", AravisOptions(), src);
	ASSERT_TRUE(st.ok()) << st.message();
	int w = 0, h = 0;
	ASSERT_TRUE(src->frameSize(w, h));
	std::unique_ptr<Detector> det = makeDetector(w, h);
	if (!det)
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	ASSERT_TRUE(src->start().ok());

	// The first frame after start may take a while (the stream thread starts).
	Frame frame;
	st = src->next(frame, 3000);
	ASSERT_TRUE(st.ok()) << st.message();
	const uint64_t firstId = frame.id;
	uint64_t lastId = frame.id;
	std::printf("[ first    ] incomplete before the first frame: %llu\n",
		    (unsigned long long)src->stats().incomplete);

	int processed = 0, detectFailures = 0, nonIncreasing = 0, wrongFormat = 0;
	Status lastError;
	calped::test::startCountingAllocations();
	while (processed < 100) {
		st = src->next(frame, 2000);
		if (!st.ok()) {
			lastError = st;
			break;
		}
		nonIncreasing += frame.id <= lastId;
		lastId = frame.id;
		wrongFormat += frame.image.format != PixelFormat::RGB8 || frame.image.width != w;
		Detections dets;
		detectFailures += !det->detect(frame.image, dets).ok();
		processed++;
	}
	const long allocations = calped::test::stopCountingAllocations();
	src->stop();

	ASSERT_EQ(processed, 100) << lastError.message();
	const SourceStats s = src->stats();
	const AravisStats t = src->transportStats();
	EXPECT_EQ(detectFailures, 0);
	EXPECT_EQ(nonIncreasing, 0);
	EXPECT_EQ(wrongFormat, 0);
	EXPECT_EQ(s.incomplete, 0u);
	EXPECT_EQ(s.timeouts, 0u);
	EXPECT_EQ(t.missingPackets, 0u);
	EXPECT_EQ(s.delivered, 101u);
	EXPECT_EQ(allocations, 0) << "operator new calls while streaming 100 frames";
	// A slow run (sanitizers, load) drops frames, and past 135 camera frames the
	// simulator's 16-bit block ids wrap: the lent ids must still grow.
	std::printf("[ stats    ] lent ids %llu..%llu: delivered %llu dropped %llu incomplete %llu "
		    "timeouts %llu resent %llu missing packets %llu underruns %llu\n",
		    (unsigned long long)firstId, (unsigned long long)lastId,
		    (unsigned long long)s.delivered, (unsigned long long)s.dropped,
		    (unsigned long long)s.incomplete, (unsigned long long)s.timeouts,
		    (unsigned long long)t.resentPackets, (unsigned long long)t.missingPackets,
		    (unsigned long long)t.underruns);
}

// The simulator's block ids start at 65401 and wrap from 65535 to 1 after 135 frames: the
// lent ids keep growing through it (a consumer that names files or measures gaps by id
// must never see them go back). About 1.5 s at 100 fps.
TEST(AravisSource, LentIdsKeepGrowingAcrossTheBlockIdWrap)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	AravisOptions options;
	options.frameRate = 100;
	ASSERT_TRUE(openCamera("127.0.0.1", "Mono8", options, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	ASSERT_TRUE(src->next(frame, 3000).ok());
	const uint64_t first = frame.id;
	uint64_t last = first;
	int nonIncreasing = 0;
	const auto deadline = Clock::now() + std::chrono::seconds(20);
	while (last <= 65535 + 20 && Clock::now() < deadline) {
		const Status st = src->next(frame, 2000);
		ASSERT_TRUE(st.ok()) << st.message();
		nonIncreasing += frame.id <= last;
		last = frame.id;
	}
	src->stop();
	const SourceStats s = src->stats();
	std::printf("[ wrap     ] lent ids %llu..%llu: delivered %llu dropped %llu incomplete %llu\n",
		    (unsigned long long)first, (unsigned long long)last, (unsigned long long)s.delivered,
		    (unsigned long long)s.dropped, (unsigned long long)s.incomplete);
	EXPECT_LE(first, 65535u) << "the simulator should start below the wrap";
	EXPECT_GT(last, 65535u + 20) << "the stream should have crossed the wrap";
	EXPECT_EQ(nonIncreasing, 0);
	EXPECT_GE(s.delivered + s.dropped + s.incomplete, last - first + 1);
}

// A slow consumer: the newest frame is lent, older complete ones are counted as dropped.
TEST(AravisSource, SlowConsumerGetsTheNewestFrameAndDropsAreCounted)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	AravisOptions options;
	options.buffers = 8;
	ASSERT_TRUE(openCamera("127.0.0.1", "Mono8", options, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	ASSERT_TRUE(src->next(frame, 3000).ok());
	const uint64_t first = frame.id;
	uint64_t last = frame.id;
	uint64_t maxGap = 0;
	for (int i = 0; i < 6; i++) {
		std::this_thread::sleep_for(std::chrono::milliseconds(150)); // ~4 frames at 25 fps
		const Status st = src->next(frame, 2000);
		ASSERT_TRUE(st.ok()) << st.message();
		maxGap = std::max<uint64_t>(maxGap, frame.id - last);
		last = frame.id;
	}
	src->stop();
	const SourceStats s = src->stats();
	EXPECT_GE(maxGap, 3u) << "the lent frame should be the newest, skipping the queued ones";
	EXPECT_GE(s.dropped, 6u * 2);
	EXPECT_EQ(s.incomplete, 0u);
	// Every frame the camera sent up to the last one lent was delivered or dropped.
	EXPECT_GE(s.delivered + s.dropped + s.incomplete, last - first + 1);
}

// Packet loss: with resend the frames are recovered; without it they are counted as
// incomplete. Either way every frame lent is intact.
TEST(AravisSource, PacketLossNeverLendsADamagedFrame)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 5); // 0.5 % of stream packets dropped
	for (const bool resend : { true, false }) {
		std::unique_ptr<AravisSource> src;
		AravisOptions options;
		options.packetResend = resend;
		ASSERT_TRUE(openCamera("127.0.0.1", "Mono8", options, src).ok());
		ASSERT_TRUE(src->start().ok());
		int lent = 0, damaged = 0;
		const auto deadline = Clock::now() + std::chrono::seconds(8);
		while (lent < 25 && Clock::now() < deadline) {
			Frame frame;
			const Status st = src->next(frame, 1000);
			if (st.code() == ErrorCode::Timeout)
				continue;
			ASSERT_TRUE(st.ok()) << st.message();
			lent++;
			// Mono8 is lent as Gray8, in place in Aravis's buffer (tight rows here).
			ASSERT_EQ(frame.image.format, PixelFormat::Gray8);
			ASSERT_EQ(frame.image.strides[0], frame.image.width);
			damaged += !isIntactRamp(frame.image);
		}
		src->stop();
		const SourceStats s = src->stats();
		const AravisStats t = src->transportStats();
		std::printf("[ loss     ] resend %s: lent %d, incomplete %llu, resent packets %llu, "
			    "missing packets %llu\n",
			    resend ? "on" : "off", lent, (unsigned long long)s.incomplete,
			    (unsigned long long)t.resentPackets, (unsigned long long)t.missingPackets);
		EXPECT_EQ(lent, 25) << (resend ? "resend on" : "resend off");
		EXPECT_EQ(damaged, 0) << (resend ? "resend on" : "resend off");
		// 0.5 % of ~190 packets per frame: most frames lose one; it must show somewhere.
		if (resend)
			EXPECT_GT(t.resentPackets + s.incomplete, 0u);
		else
			EXPECT_GT(s.incomplete, 0u);
	}
}

// The camera dies mid-stream (SIGKILL): CameraLost within a bounded time, and stop() and
// destruction return cleanly. Run under valgrind by the `ports-aravis-leaks` test.
TEST(AravisSource, KilledCameraIsReportedAsCameraLost)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	AravisOptions options;
	options.lostAfterMs = 1000;
	ASSERT_TRUE(openCamera("127.0.0.1", "Mono8", options, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	for (int i = 0; i < 5; i++)
		ASSERT_TRUE(src->next(frame, 3000).ok());
	fake.kill();
	const auto killed = Clock::now();
	Status st;
	int calls = 0;
	do {
		st = src->next(frame, 200);
		calls++;
	} while (st.code() != ErrorCode::CameraLost &&
		 (st.ok() || st.code() == ErrorCode::Timeout) && Clock::now() - killed < std::chrono::seconds(20));
	const double seconds = std::chrono::duration<double>(Clock::now() - killed).count();
	std::printf("[ lost     ] CameraLost after %.2f s (%d next() calls): %s\n", seconds, calls,
		    st.message());
	EXPECT_EQ(st.code(), ErrorCode::CameraLost) << st.message();
	EXPECT_LT(seconds, 10.0);
	EXPECT_FALSE(src->connected());
	// Later calls keep saying so; stop() twice is harmless.
	EXPECT_EQ(src->next(frame, 10).code(), ErrorCode::CameraLost);
	src->stop();
	src->stop();
	src.reset();
}

// With reconnect, a restarted camera is found again and counted in restarts.
TEST(AravisSource, ReconnectsAfterTheCameraRestarts)
{
	FakeGvCamera fake;
	START_FAKE_CAMERA(fake, "127.0.0.1", 0);
	std::unique_ptr<AravisSource> src;
	AravisOptions options;
	options.lostAfterMs = 1000;
	options.reconnect = true;
	options.reconnectEveryMs = 200;
	ASSERT_TRUE(openCamera("127.0.0.1", "Mono8", options, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	for (int i = 0; i < 5; i++) // a few frames: their interval is measured
		ASSERT_TRUE(src->next(frame, 3000).ok());
	fake.kill();
	// Wait until the port notices, then bring the camera back.
	const auto killed = Clock::now();
	while (src->connected() && Clock::now() - killed < std::chrono::seconds(15))
		src->next(frame, 200);
	ASSERT_FALSE(src->connected()) << "the loss was never noticed";
	std::string why;
	ASSERT_TRUE(fake.start("127.0.0.1", 0, why)) << why;
	const auto restarted = Clock::now();
	int frames = 0;
	while (frames < 10 && Clock::now() - restarted < std::chrono::seconds(15)) {
		const Status st = src->next(frame, 500);
		ASSERT_TRUE(st.ok() || st.code() == ErrorCode::Timeout) << st.message();
		frames += st.ok();
	}
	src->stop();
	EXPECT_EQ(frames, 10);
	EXPECT_EQ(src->stats().restarts, 1u);
	EXPECT_EQ(src->transportStats().lostEvents, 1u);
	// The frames a camera makes while away are estimated from the time and the interval
	// (this simulator made none, but a camera that only lost its link would have).
	EXPECT_GT(src->transportStats().lostAcrossReconnects, 0u);
	EXPECT_GE(src->stats().dropped, src->transportStats().lostAcrossReconnects);
	std::printf("[ restart  ] stream back %.2f s after the loss was noticed; %llu frames estimated lost\n",
		    src->transportStats().lastReconnectSeconds,
		    static_cast<unsigned long long>(src->transportStats().lostAcrossReconnects));
}

// --- Real pixels through a camera path ---

namespace {

struct PetsFrames {
	std::vector<std::vector<uint8_t>> rgb;
	int width = 0, height = 0;
};

// Aravis's fake camera calls this for every frame it makes: we copy a PETS frame in.
void fillWithPets(ArvBuffer *buffer, void *data, guint32, guint32, ArvPixelFormat)
{
	const PetsFrames &pets = *static_cast<const PetsFrames *>(data);
	// Aravis 0.8.26 reports 0 bytes for these buffers; their geometry, set by the fake
	// camera from its registers, says what they hold (the port allocated them to fit).
	uint8_t *dst = static_cast<uint8_t *>(const_cast<void *>(arv_buffer_get_data(buffer, nullptr)));
	const std::vector<uint8_t> &src = pets.rgb[arv_buffer_get_frame_id(buffer) % pets.rgb.size()];
	if (dst && arv_buffer_get_image_width(buffer) == pets.width &&
	    arv_buffer_get_image_height(buffer) == pets.height &&
	    arv_buffer_get_image_pixel_format(buffer) == ARV_PIXEL_FORMAT_RGB_8_PACKED)
		std::memcpy(dst, src.data(), src.size());
}

bool sameDetections(const Detections &a, const std::vector<Detection> &b)
{
	if (a.count != static_cast<int>(b.size()))
		return false;
	for (int i = 0; i < a.count; i++) {
		const Detection &x = a.items[i], &y = b[static_cast<size_t>(i)];
		if (x.x != y.x || x.y != y.y || x.w != y.w || x.h != y.h || x.score != y.score)
			return false;
	}
	return true;
}

} // namespace

// PETS frames go through Aravis's in-process Fake camera (RGB8, 768x576): every lent
// frame carries exactly one of the PETS frames' pixels, and its detections equal, box for
// box and score for score, those of the file source on the same frame.
TEST(AravisSource, PetsFramesThroughTheFakeCameraDetectLikeTheFileRun)
{
	constexpr int kFrames = 4;
	const std::string first = calped::test::petsFrame(1);
	if (first.empty())
		GTEST_SKIP() << "PETS frames not available (data/pets/frames): skipping";

	// The file run: the same frames from a folder through the file source.
	char dirTemplate[] = "/tmp/calped-pets-XXXXXX";
	ASSERT_NE(mkdtemp(dirTemplate), nullptr);
	const std::string dir = dirTemplate;
	for (int k = 1; k <= kFrames; k++) {
		const std::string target = std::filesystem::absolute(calped::test::petsFrame(k)).string();
		char name[32];
		std::snprintf(name, sizeof(name), "/%06d.png", k);
		ASSERT_EQ(symlink(target.c_str(), (dir + name).c_str()), 0);
	}
	FileSourceOptions fileOptions;
	fileOptions.path = dir;
	std::unique_ptr<FileSource> files;
	ASSERT_TRUE(FileSource::open(fileOptions, files).ok());
	int w = 0, h = 0;
	ASSERT_TRUE(files->frameSize(w, h));
	std::unique_ptr<Detector> det = makeDetector(w, h);
	if (!det)
		GTEST_SKIP() << "the INRIA model is not available (../shared): skipping";
	PetsFrames pets;
	pets.width = w;
	pets.height = h;
	std::vector<std::vector<Detection>> expected;
	ASSERT_TRUE(files->start().ok());
	Frame frame;
	while (files->next(frame, 1000).ok()) {
		ASSERT_EQ(frame.image.format, PixelFormat::RGB8);
		pets.rgb.emplace_back(frame.image.planes[0],
				      frame.image.planes[0] + static_cast<size_t>(w) * h * 3);
		Detections dets;
		ASSERT_TRUE(det->detect(frame.image, dets).ok());
		expected.emplace_back(dets.begin(), dets.end());
	}
	files->stop();
	for (int k = 1; k <= kFrames; k++) {
		char name[32];
		std::snprintf(name, sizeof(name), "/%06d.png", k);
		unlink((dir + name).c_str());
	}
	rmdir(dir.c_str());
	ASSERT_EQ(pets.rgb.size(), static_cast<size_t>(kFrames));

	// The camera run.
	arv_enable_interface("Fake");
	arv_update_device_list();
	std::string fakeId;
	for (unsigned i = 0; i < arv_get_n_devices(); i++)
		if (std::strcmp(arv_get_device_protocol(i), "Fake") == 0)
			fakeId = arv_get_device_id(i);
	ASSERT_FALSE(fakeId.empty()) << "Aravis's Fake interface lists no device";
	AravisOptions options;
	options.width = w;
	options.height = h;
	std::unique_ptr<AravisSource> src;
	Status st = openCamera(fakeId, "RGB8", options, src);
	ASSERT_TRUE(st.ok()) << st.message();
	ArvDevice *device = arv_camera_get_device(src->arvCamera());
	ASSERT_TRUE(ARV_IS_FAKE_DEVICE(device));
	// The Fake stream runs from open() on and fills every buffer it is given with its own
	// pattern until ours is installed. A loaded machine can pause here for frames; the
	// pause makes that certain: the port must not lend a frame made before start().
	std::this_thread::sleep_for(std::chrono::milliseconds(200));
	arv_fake_camera_set_fill_pattern(arv_fake_device_get_fake_camera(ARV_FAKE_DEVICE(device)),
					 fillWithPets, &pets);
	ASSERT_TRUE(src->start().ok());

	int seen[kFrames] = { 0 }, unknown = 0, mismatched = 0, lent = 0;
	const size_t bytes = static_cast<size_t>(w) * h * 3;
	const auto deadline = Clock::now() + std::chrono::seconds(20);
	while (lent < 12 && Clock::now() < deadline) {
		st = src->next(frame, 2000);
		ASSERT_TRUE(st.ok()) << st.message() << " (incomplete " << src->stats().incomplete
				     << ", other " << src->transportStats().incompleteOther << ")";
		ASSERT_EQ(frame.image.format, PixelFormat::RGB8);
		ASSERT_EQ(frame.image.width, w);
		ASSERT_EQ(frame.image.height, h);
		ASSERT_EQ(frame.image.strides[0], 3 * w);
		int k = -1;
		for (int i = 0; i < kFrames && k < 0; i++)
			if (std::memcmp(frame.image.planes[0], pets.rgb[static_cast<size_t>(i)].data(), bytes) == 0)
				k = i;
		lent++;
		if (k < 0) {
			unknown++;
			continue;
		}
		seen[k]++;
		Detections dets;
		ASSERT_TRUE(det->detect(frame.image, dets).ok());
		mismatched += !sameDetections(dets, expected[static_cast<size_t>(k)]);
	}
	src->stop();
	EXPECT_EQ(lent, 12);
	EXPECT_EQ(unknown, 0) << "frames whose pixels are none of the PETS frames";
	EXPECT_EQ(mismatched, 0) << "frames whose detections differ from the file run";
	int distinct = 0;
	for (int n : seen)
		distinct += n > 0;
	EXPECT_GE(distinct, 2) << "the camera should cycle through the frames";
	size_t expectedBoxes = 0;
	for (const auto &e : expected)
		expectedBoxes += e.size();
	std::printf("[ pets     ] lent %d: PETS frames 1-4 seen %d/%d/%d/%d times; file-run boxes "
		    "%zu/%zu/%zu/%zu; mismatched %d, unknown %d\n",
		    lent, seen[0], seen[1], seen[2], seen[3], expected[0].size(), expected[1].size(),
		    expected[2].size(), expected[3].size(), mismatched, unknown);
	EXPECT_GT(expectedBoxes, 0u) << "PETS frames with people should give detections";
}

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	const int rc = RUN_ALL_TESTS();
	arv_shutdown();
	return rc;
}
