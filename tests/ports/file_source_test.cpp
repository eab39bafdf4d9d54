// SPDX-License-Identifier: BSD-2-Clause
// The file source: image folders and videos as a virtual camera (order, loop, pacing,
// frame limits, errors that name the file) and no allocation per frame.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "common/alloc_counter.h"
#include "file_source.h"
#include "probe_output.h"
#include "video_pipe.h"

using namespace calped;
using namespace calped::ports;
namespace fs = std::filesystem;

namespace {

// A fresh folder under the system's temporary directory, removed afterwards.
class TempDir
{
public:
	TempDir()
	{
		char tmpl[] = "/tmp/calped-file-source-XXXXXX";
		path_ = mkdtemp(tmpl) ? tmpl : "";
	}
	~TempDir()
	{
		std::error_code ec;
		fs::remove_all(path_, ec);
	}
	const std::string &path() const { return path_; }

private:
	std::string path_;
};

// Image k is filled with the value k in every channel: frames are told apart by a pixel.
void writeImage(const std::string &path, int w, int h, uint8_t value)
{
	std::vector<uint8_t> px(static_cast<size_t>(w) * h * 3, value);
	ASSERT_TRUE(stbi_write_png(path.c_str(), w, h, 3, px.data(), w * 3));
}

bool haveFfmpeg()
{
	return std::system("ffmpeg -version >/dev/null 2>&1") == 0 &&
	       std::system("ffprobe -version >/dev/null 2>&1") == 0;
}

// A 10-frame 64x48 test video (ffmpeg's testsrc), or "" without ffmpeg.
std::string makeVideo(const TempDir &dir)
{
	const std::string path = dir.path() + "/clip.avi";
	const std::string cmd = "ffmpeg -loglevel error -f lavfi -i testsrc=size=64x48:rate=10 "
				"-frames:v 10 -c:v ffv1 -y " + path + " 2>/dev/null";
	return std::system(cmd.c_str()) == 0 ? path : "";
}

} // namespace

TEST(FileSource, FolderPlaysInNameOrderThenEnds)
{
	TempDir dir;
	writeImage(dir.path() + "/b.png", 8, 6, 2);
	writeImage(dir.path() + "/a.png", 8, 6, 1);
	writeImage(dir.path() + "/c.png", 10, 4, 3); // frames may differ in size
	std::FILE *f = std::fopen((dir.path() + "/notes.txt").c_str(), "w");
	std::fclose(f);

	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = dir.path();
	ASSERT_TRUE(FileSource::open(o, src).ok());
	EXPECT_EQ(src->imageCount(), 3u);
	int w = 0, h = 0;
	ASSERT_TRUE(src->frameSize(w, h));
	EXPECT_EQ(w, 10); // the largest of each dimension
	EXPECT_EQ(h, 6);
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	for (int k = 1; k <= 3; k++) {
		const Status st = src->next(frame, 100);
		ASSERT_TRUE(st.ok()) << st.message();
		EXPECT_EQ(frame.id, static_cast<uint64_t>(k));
		EXPECT_EQ(frame.image.format, PixelFormat::RGB8);
		EXPECT_EQ(frame.image.planes[0][0], k);
		EXPECT_EQ(frame.image.width, k == 3 ? 10 : 8);
		EXPECT_EQ(frame.image.strides[0], 3 * frame.image.width);
	}
	EXPECT_EQ(src->next(frame, 100).code(), ErrorCode::EndOfStream);
	EXPECT_EQ(src->stats().delivered, 3u);
	src->stop();
	src->stop();
}

TEST(FileSource, LoopsAndStopsAtMaxFrames)
{
	TempDir dir;
	writeImage(dir.path() + "/1.png", 4, 4, 1);
	writeImage(dir.path() + "/2.png", 4, 4, 2);
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = dir.path();
	o.loop = true;
	o.maxFrames = 5;
	ASSERT_TRUE(FileSource::open(o, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	std::vector<int> values;
	Status st;
	while ((st = src->next(frame, 100)).ok())
		values.push_back(frame.image.planes[0][0]);
	EXPECT_EQ(st.code(), ErrorCode::EndOfStream);
	EXPECT_EQ(values, (std::vector<int>{ 1, 2, 1, 2, 1 }));
	EXPECT_EQ(frame.id, 5u);
}

TEST(FileSource, PacesAtTheFrameRate)
{
	TempDir dir;
	writeImage(dir.path() + "/1.png", 4, 4, 1);
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = dir.path();
	o.loop = true;
	o.fps = 50;
	ASSERT_TRUE(FileSource::open(o, src).ok());
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	const auto t0 = std::chrono::steady_clock::now();
	for (int i = 0; i < 6; i++)
		ASSERT_TRUE(src->next(frame, 1000).ok());
	const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	// Frame k is due k / 50 s after start: six frames cannot come before 100 ms.
	EXPECT_GE(ms, 99.0);
	// A timeout shorter than the frame period is reported and counted.
	src->stop();
	o.fps = 1;
	ASSERT_TRUE(FileSource::open(o, src).ok());
	ASSERT_TRUE(src->start().ok());
	ASSERT_TRUE(src->next(frame, 10).ok()); // frame 0 is due at once
	EXPECT_EQ(src->next(frame, 10).code(), ErrorCode::Timeout);
	EXPECT_EQ(src->stats().timeouts, 1u);
}

TEST(FileSource, ErrorsNameTheFile)
{
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = "/nonexistent/calped-frames";
	Status st = FileSource::open(o, src);
	EXPECT_EQ(st.code(), ErrorCode::IoError);
	EXPECT_NE(std::strstr(st.message(), "/nonexistent/calped-frames"), nullptr) << st.message();

	TempDir dir;
	o.path = dir.path();
	st = FileSource::open(o, src);
	EXPECT_EQ(st.code(), ErrorCode::IoError) << "an empty folder is an error, not an empty run";

	const std::string bad = dir.path() + "/broken.png";
	std::FILE *f = std::fopen(bad.c_str(), "w");
	std::fputs("not a png", f);
	std::fclose(f);
	st = FileSource::open(o, src);
	EXPECT_EQ(st.code(), ErrorCode::IoError);
	EXPECT_NE(std::strstr(st.message(), "broken.png"), nullptr) << st.message();

	o.fps = -1;
	EXPECT_EQ(FileSource::open(o, src).code(), ErrorCode::InvalidArgument);
}

TEST(FileSource, NextBeforeStartIsRefused)
{
	TempDir dir;
	writeImage(dir.path() + "/1.png", 4, 4, 1);
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = dir.path();
	ASSERT_TRUE(FileSource::open(o, src).ok());
	Frame frame;
	EXPECT_EQ(src->next(frame, 10).code(), ErrorCode::InvalidArgument);
}

TEST(FileSource, VideoPlaysEveryFrameAndLoops)
{
	if (!haveFfmpeg())
		GTEST_SKIP() << "ffmpeg/ffprobe not installed: skipping";
	TempDir dir;
	const std::string video = makeVideo(dir);
	ASSERT_FALSE(video.empty());
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = video;
	ASSERT_TRUE(FileSource::open(o, src).ok());
	EXPECT_TRUE(src->isVideo());
	int w = 0, h = 0;
	ASSERT_TRUE(src->frameSize(w, h));
	EXPECT_EQ(w, 64);
	EXPECT_EQ(h, 48);
	ASSERT_TRUE(src->start().ok());
	Frame frame;
	int n = 0;
	std::vector<uint8_t> firstFrame;
	Status st;
	while ((st = src->next(frame, 1000)).ok()) {
		if (n == 0)
			firstFrame.assign(frame.image.planes[0], frame.image.planes[0] + 64 * 48 * 3);
		n++;
	}
	EXPECT_EQ(st.code(), ErrorCode::EndOfStream) << st.message();
	EXPECT_EQ(n, 10);

	// Looping restarts the decoder: frame 11 is frame 1 again.
	o.loop = true;
	o.maxFrames = 11;
	ASSERT_TRUE(FileSource::open(o, src).ok());
	ASSERT_TRUE(src->start().ok());
	for (int i = 0; i < 11; i++)
		ASSERT_TRUE(src->next(frame, 1000).ok()) << i;
	EXPECT_EQ(std::memcmp(frame.image.planes[0], firstFrame.data(), firstFrame.size()), 0);
	EXPECT_EQ(src->next(frame, 1000).code(), ErrorCode::EndOfStream);
}

TEST(FileSource, BadVideoAndMissingFfmpegAreClearErrors)
{
	TempDir dir;
	const std::string bad = dir.path() + "/broken.mp4";
	std::FILE *f = std::fopen(bad.c_str(), "w");
	std::fputs("not a video", f);
	std::fclose(f);
	std::unique_ptr<FileSource> src;
	FileSourceOptions o;
	o.path = bad;
	Status st = FileSource::open(o, src);
	EXPECT_EQ(st.code(), ErrorCode::IoError);
	EXPECT_NE(std::strstr(st.message(), "broken.mp4"), nullptr) << st.message();

	const char *oldPath = std::getenv("PATH");
	const std::string saved = oldPath ? oldPath : "";
	setenv("PATH", "/nonexistent-calped-bin", 1);
	st = FileSource::open(o, src);
	setenv("PATH", saved.c_str(), 1);
	EXPECT_EQ(st.code(), ErrorCode::IoError);
	EXPECT_NE(std::strstr(st.message(), "install ffmpeg"), nullptr) << st.message();
}

// An ffprobe that writes 1 MiB on stderr before its answer on stdout: read one pipe after
// the other, the probe waited for stdout's end while ffprobe waited for room on stderr.
TEST(FileSource, ProbeDrainsFfprobesStdoutAndStderrTogether)
{
	TempDir dir;
	const std::string video = dir.path() + "/any.mp4";
	std::FILE *f = std::fopen(video.c_str(), "w");
	std::fputs("stand-in", f);
	std::fclose(f);
	const std::string fake = dir.path() + "/ffprobe";
	f = std::fopen(fake.c_str(), "w");
	std::fputs("#!/bin/sh\nhead -c 1048576 /dev/zero | tr '\\0' w >&2\necho 320x240\n", f);
	std::fclose(f);
	fs::permissions(fake, fs::perms::owner_all);

	const char *oldPath = std::getenv("PATH");
	const std::string saved = oldPath ? oldPath : "";
	setenv("PATH", (dir.path() + ":" + saved).c_str(), 1);
	int w = 0, h = 0;
	const Status st = probeVideo(video, w, h);
	setenv("PATH", saved.c_str(), 1);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(w, 320);
	EXPECT_EQ(h, 240);
}

TEST(FileSource, ProbedSizeIsTwoNumbersAndNothingElse)
{
	int w = 0, h = 0;
	auto parse = [&](const std::string &t) { return parseProbedSize(t.data(), t.size(), w, h); };
	EXPECT_TRUE(parse("768x576\n"));
	EXPECT_EQ(w, 768);
	EXPECT_EQ(h, 576);
	EXPECT_TRUE(parse("16384x1"));
	for (const char *bad : { "", "x", "768x", "x576", "768x576\n640x480\n", "0x576", "768x0",
				 "-768x576", "+768x576", " 768x576", "768 x 576", "768x576junk",
				 "16385x576", "99999999999999999999x576", "768X576", "0768x576",
				 "011x02980\r\n" /* found by fuzzing: printed back as 11x2980 */ })
		EXPECT_FALSE(parse(bad)) << bad;
	EXPECT_FALSE(parse(std::string("768x576\0", 8))); // a NUL is not white space
}

TEST(FileSource, AllocationCounterSeesAllocations)
{
	// The counter must work, or the allocation test below proves nothing.
	calped::test::startCountingAllocations();
	std::vector<int> *v = new std::vector<int>(100);
	const long n = calped::test::stopCountingAllocations();
	delete v;
	EXPECT_GE(n, 1);
}

// The frame buffer is fixed at start(): next() itself allocates nothing (stb_image's
// internal malloc is not operator new; the video path has no allocation at all).
TEST(FileSource, NextAllocatesNothing)
{
	TempDir dir;
	for (int k = 1; k <= 3; k++)
		writeImage(dir.path() + "/" + std::to_string(k) + ".png", 16, 12, static_cast<uint8_t>(k));
	std::vector<std::string> inputs = { dir.path() };
	if (haveFfmpeg()) {
		const std::string video = makeVideo(dir);
		ASSERT_FALSE(video.empty());
		fs::rename(video, dir.path() + "/../" + fs::path(dir.path()).filename().string() + ".avi");
		inputs.push_back(dir.path() + "/../" + fs::path(dir.path()).filename().string() + ".avi");
	}
	for (const std::string &input : inputs) {
		std::unique_ptr<FileSource> src;
		FileSourceOptions o;
		o.path = input;
		o.loop = true;
		o.maxFrames = 8;
		ASSERT_TRUE(FileSource::open(o, src).ok());
		ASSERT_TRUE(src->start().ok());
		Frame frame;
		ASSERT_TRUE(src->next(frame, 1000).ok());
		int frames = 0;
		calped::test::startCountingAllocations();
		while (frames < 5 && src->next(frame, 1000).ok())
			frames++;
		const long allocations = calped::test::stopCountingAllocations();
		EXPECT_EQ(frames, 5) << input;
		EXPECT_EQ(allocations, 0) << input;
	}
	if (inputs.size() > 1)
		fs::remove(inputs[1]);
}
