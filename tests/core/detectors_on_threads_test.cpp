// SPDX-License-Identifier: BSD-2-Clause
// The threading contract of detector.h: separate detectors on separate threads, sharing
// one Model read-only, give exactly what each gives alone (run under TSan to see races).
#include <thread>
#include <vector>
#include <gtest/gtest.h>

#include <calped/detector.h>

#include "synthetic.h"

using namespace calped;

namespace {

constexpr int kWidth = 320, kHeight = 240, kFrames = 3, kThreads = 4;

struct DetectorRun {
	std::vector<Detection> detections;
	uint64_t windows = 0, candidates = 0;
	bool ok = false;
};

// One detector over its thread's frames (seeded by `thread`), everything it found.
DetectorRun detectFrames(const Model &model, int thread)
{
	DetectorRun run;
	DetectorConfig cfg;
	cfg.maxWidth = kWidth;
	cfg.maxHeight = kHeight;
	cfg.cascadeThreshold = -1.0f; // many candidates, so that a mix-up shows
	std::unique_ptr<Detector> det;
	if (!Detector::create(model, cfg, det).ok())
		return run;
	for (int f = 0; f < kFrames; f++) {
		const auto img = test::randomImage(uint32_t(100 * thread + f), kWidth, kHeight);
		Detections d;
		if (!det->detect(ImageView::rgb8(img.data(), kWidth, kHeight), d).ok())
			return run;
		run.detections.insert(run.detections.end(), d.begin(), d.end());
		run.windows += det->lastStats().windows;
		run.candidates += det->lastStats().candidates;
	}
	run.ok = true;
	return run;
}

void expectSame(const DetectorRun &a, const DetectorRun &b, int thread)
{
	ASSERT_TRUE(a.ok && b.ok) << "thread " << thread;
	EXPECT_EQ(a.windows, b.windows) << "thread " << thread;
	EXPECT_EQ(a.candidates, b.candidates) << "thread " << thread;
	ASSERT_EQ(a.detections.size(), b.detections.size()) << "thread " << thread;
	for (size_t i = 0; i < a.detections.size(); i++) {
		const Detection &x = a.detections[i], &y = b.detections[i];
		EXPECT_TRUE(x.x == y.x && x.y == y.y && x.w == y.w && x.h == y.h && x.score == y.score)
			<< "thread " << thread << " detection " << i;
	}
}

} // namespace

TEST(DetectorsOnThreads, SeparateDetectorsSharingOneModelMatchTheSerialRun)
{
	const Model model = test::randomModel(7);
	std::vector<DetectorRun> serial(kThreads), parallel(kThreads);
	for (int t = 0; t < kThreads; t++)
		serial[t] = detectFrames(model, t);
	std::vector<std::thread> threads;
	for (int t = 0; t < kThreads; t++)
		threads.emplace_back([&, t] { parallel[t] = detectFrames(model, t); });
	for (std::thread &th : threads)
		th.join();
	for (int t = 0; t < kThreads; t++)
		expectSame(serial[t], parallel[t], t);
	// The frames differ per thread: equal results are not a trivially equal input.
	EXPECT_NE(serial[0].candidates, 0u);
}
