// SPDX-License-Identifier: BSD-2-Clause
// Detection CSV round trip and errors, and the bytes a run's process sends back.
#include <cstdio>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "dets_csv.h"
#include "runner.h"
#include "test_paths.h"

namespace calped::eval_tool {
namespace {

std::string tempPath(const std::string &name)
{
	return test::envOr("CALPED_BUILD_DIR", ".") + "/eval-test-" + std::to_string(getpid()) + "-" + name;
}

TEST(DetectionsCsv, RoundTripIsExact)
{
	SequenceDetections d(3);
	d[0].push_back({ Box{ 499.27710843f, 155.55f, 31.5966926f, 77.0651f }, 100.76113891f });
	d[2].push_back({ Box{ -3.25f, 0.1f, 40, 98.5f }, -0.5f });
	d[2].push_back({ Box{ 1e-3f, 1e4f, 1.0f / 3.0f, 2.0f / 7.0f }, 1.0f / 65536.0f });
	const std::string path = tempPath("roundtrip.csv");
	std::string error;
	ASSERT_TRUE(writeDetectionsCsv(path, d, error)) << error;
	SequenceDetections back;
	ASSERT_TRUE(readDetectionsCsv(path, 3, back, error)) << error;
	std::remove(path.c_str());
	ASSERT_EQ(back.size(), 3u); // frame 2 has no rows; frame 3 sets the size
	EXPECT_TRUE(back[1].empty());
	ASSERT_EQ(back[2].size(), 2u);
	for (size_t f = 0; f < 3; f++) {
		for (size_t i = 0; i < d[f].size(); i++) {
			EXPECT_EQ(back[f][i].box.x, d[f][i].box.x);
			EXPECT_EQ(back[f][i].box.y, d[f][i].box.y);
			EXPECT_EQ(back[f][i].box.w, d[f][i].box.w);
			EXPECT_EQ(back[f][i].box.h, d[f][i].box.h);
			EXPECT_EQ(back[f][i].score, d[f][i].score);
		}
	}
}

TEST(DetectionsCsv, DetectorFloatsGiveShortNumbers)
{
	EXPECT_EQ(shortestDecimal(floatAsDecimal(155.55f)), "155.550003");
	EXPECT_EQ(shortestDecimal(floatAsDecimal(2.0f)), "2");
	EXPECT_EQ(shortestDecimal(0.1), "0.1");
}

TEST(DetectionsCsv, FramesBeyondTheScoredOnesAreAnError)
{
	SequenceDetections d(5);
	d[4].push_back({ Box{ 1, 2, 3, 4 }, 5 });
	const std::string path = tempPath("beyond.csv");
	std::string error;
	ASSERT_TRUE(writeDetectionsCsv(path, d, error)) << error;
	SequenceDetections back;
	EXPECT_FALSE(readDetectionsCsv(path, 4, back, error));
	std::remove(path.c_str());
	EXPECT_NE(error.find(path + ":2: frame 5 is beyond the 4 frames scored"), std::string::npos)
		<< error;
}

TEST(DetectionsCsv, MalformedFilesNameFileAndLine)
{
	SequenceDetections d;
	std::string error;
	const std::string header = test::dataPath("dets_bad_header.csv");
	EXPECT_FALSE(readDetectionsCsv(header, 0, d, error));
	EXPECT_EQ(error.rfind(header + ":1: ", 0), 0u) << error;
	const std::string row = test::dataPath("dets_bad_row.csv");
	EXPECT_FALSE(readDetectionsCsv(row, 0, d, error));
	EXPECT_EQ(error.rfind(row + ":3: expected 6 comma-separated fields", 0), 0u) << error;
}

// A 1 MiB field of control characters and invalid UTF-8: the message quotes a short,
// escaped excerpt (lib/src/text/excerpt.h), one printable line.
TEST(DetectionsCsv, HostileFieldsAreQuotedShortAndEscaped)
{
	std::string field;
	while (field.size() < (1u << 20))
		field += "7\x01\x1b[2J\xff\xfe\r";
	const std::string path = tempPath("hostile.csv");
	std::FILE *f = std::fopen(path.c_str(), "wb");
	ASSERT_NE(f, nullptr);
	const std::string text = "frame,x,y,w,h,score\n1,2,3,4,5,6\n1," + field + ",3,4,5,6\n";
	std::fwrite(text.data(), 1, text.size(), f);
	std::fclose(f);
	SequenceDetections d;
	std::string error;
	EXPECT_FALSE(readDetectionsCsv(path, 0, d, error));
	std::remove(path.c_str());
	EXPECT_LT(error.size(), path.size() + 160) << error.substr(0, 300);
	for (unsigned char c : error)
		ASSERT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(c) << " in " << error.substr(0, 300);
	// Each control byte and each invalid byte is one '?' (written \x3f: no trigraphs here).
	EXPECT_NE(error.find(":3: x \"7\x3f\x3f[2J\x3f\x3f\x3f" "7"), std::string::npos) << error;
	EXPECT_NE(error.find("...\" is not a finite number"), std::string::npos) << error;
}

// calped-detect's CSV (three world columns, empty without a calibration) scores as it is.
TEST(DetectionsCsv, ReadsCalpedDetectsCsv)
{
	const std::string path = tempPath("detect.csv");
	FILE *f = std::fopen(path.c_str(), "w");
	ASSERT_NE(f, nullptr);
	std::fputs("frame,x,y,w,h,score,ground_x,ground_y,world_height\n"
		   "1,499.93,156.25,30.27,73.84,102.5539,-3.971,-7.324,1.782\n"
		   "2,10.00,20.00,41.00,100.00,55.1234,,,\n",
		   f);
	std::fclose(f);
	SequenceDetections d;
	std::string error;
	ASSERT_TRUE(readDetectionsCsv(path, 2, d, error)) << error;
	std::remove(path.c_str());
	ASSERT_EQ(d.size(), 2u);
	ASSERT_EQ(d[0].size(), 1u);
	EXPECT_EQ(d[0][0].box.x, 499.93);
	EXPECT_EQ(d[1][0].score, 55.1234);
}

TEST(RunBytes, EncodeDecodeRoundTrip)
{
	RunResult run;
	run.frames = 3;
	run.counters.frames = 3;
	run.counters.levelsMin = 29;
	run.counters.windowsMean = 570135;
	run.counters.peakRssKib = 12345;
	run.detections.resize(3);
	run.detections[1].push_back({ Box{ 1, 2, 3, 4 }, 5 });
	RunResult back;
	std::string error;
	ASSERT_TRUE(decodeRun(encodeRun(run), back, error)) << error;
	EXPECT_EQ(back.frames, 3);
	EXPECT_EQ(back.counters.levelsMin, 29);
	EXPECT_EQ(back.counters.windowsMean, 570135);
	EXPECT_EQ(back.counters.peakRssKib, 12345);
	ASSERT_EQ(back.detections.size(), 3u);
	ASSERT_EQ(back.detections[1].size(), 1u);
	EXPECT_EQ(back.detections[1][0].score, 5);

	std::vector<unsigned char> bytes = encodeRun(run);
	bytes.resize(bytes.size() - 1);
	EXPECT_FALSE(decodeRun(bytes, back, error));
	EXPECT_FALSE(decodeRun({}, back, error));
}

} // namespace
} // namespace calped::eval_tool
