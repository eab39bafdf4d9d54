// SPDX-License-Identifier: BSD-2-Clause
// Detections on PETS frames 1-50 against Dollár's toolbox (acfDetect with the INRIA
// model), at native size and with the frame upscaled 2x.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <calped/detector.h>

#include "test_data.h"

using namespace calped;

namespace {

struct Box {
	double x, y, w, h, score;
};

std::map<int, std::vector<Box>> readDetections(const std::string &path)
{
	std::map<int, std::vector<Box>> out;
	std::ifstream f(path);
	std::string line;
	std::getline(f, line); // header
	while (std::getline(f, line)) {
		std::replace(line.begin(), line.end(), ',', ' ');
		std::istringstream s(line);
		int frame;
		Box b;
		if (s >> frame >> b.x >> b.y >> b.w >> b.h >> b.score)
			out[frame].push_back(b);
	}
	return out;
}

double iou(const Box &a, const Box &b)
{
	const double iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
	const double ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
	if (iw <= 0 || ih <= 0)
		return 0;
	const double inter = iw * ih;
	return inter / (a.w * a.h + b.w * b.h - inter);
}

// Fraction of `from` boxes scoring >= minScore that have a box of `to` at IoU >= 0.8;
// the relative score differences of those matches go to *scoreDiffs.
double matchedFraction(const std::map<int, std::vector<Box>> &from,
		       const std::map<int, std::vector<Box>> &to, double minScore,
		       std::vector<double> *scoreDiffs, int *considered)
{
	int n = 0, matched = 0;
	for (const auto &[frame, boxes] : from) {
		auto it = to.find(frame);
		for (const Box &a : boxes) {
			if (a.score < minScore)
				continue;
			n++;
			const Box *best = nullptr;
			double bestIou = 0;
			if (it != to.end())
				for (const Box &b : it->second)
					if (iou(a, b) > bestIou) {
						bestIou = iou(a, b);
						best = &b;
					}
			if (best && bestIou >= 0.8) {
				matched++;
				if (scoreDiffs)
					scoreDiffs->push_back(std::fabs(best->score - a.score) / std::fabs(a.score));
			}
		}
	}
	*considered = n;
	return n ? double(matched) / n : 0;
}

void runParity(const char *refFile, double resize, double minMatched, bool resizeInPyramid = false)
{
	const std::string shared = test::sharedDir();
	const std::string blobPath = test::inriaModelBlob();
	if (shared.empty() || blobPath.empty() || test::petsFrame(1).empty())
		GTEST_SKIP() << "needs ../shared, calped-convert and data/pets/frames (scripts/fetch-pets.sh)";
	std::vector<uint8_t> blob;
	ASSERT_TRUE(test::readFile(blobPath, blob));
	Model model;
	Status st = loadModel(blob.data(), blob.size(), model);
	ASSERT_TRUE(st.ok()) << st.message();
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = resize;
	cfg.resizeAt = resizeInPyramid ? ResizeAt::Pyramid : ResizeAt::Frame;
	std::unique_ptr<Detector> det;
	st = Detector::create(model, cfg, det);
	ASSERT_TRUE(st.ok()) << st.message();

	// CALPED_PARITY_FRAMES shortens the run (the sanitizer build uses it).
	int frames = 50;
	if (const char *env = std::getenv("CALPED_PARITY_FRAMES"))
		frames = std::clamp(std::atoi(env), 1, 50);
	auto ref = readDetections(shared + "/reference/dollar-toolbox-pets/" + refFile);
	for (auto it = ref.begin(); it != ref.end();)
		it = it->first > frames ? ref.erase(it) : std::next(it);
	std::map<int, std::vector<Box>> ours;
	double ms = 0;
	for (int k = 1; k <= frames; k++) {
		test::RgbImage img;
		ASSERT_TRUE(test::loadRgb(test::petsFrame(k), img));
		Detections d;
		st = det->detect(ImageView::rgb8(img.pixels.data(), img.width, img.height), d);
		ASSERT_TRUE(st.ok()) << st.message();
		ms += det->lastStats().msTotal;
		for (const Detection &b : d)
			ours[k].push_back({ b.x, b.y, b.w, b.h, b.score });
	}

	std::vector<double> diffs;
	int nRef = 0, nOurs = 0;
	const double refFound = matchedFraction(ref, ours, 10.0, &diffs, &nRef);
	const double oursFound = matchedFraction(ours, ref, 10.0, nullptr, &nOurs);
	std::sort(diffs.begin(), diffs.end());
	const double median = diffs.empty() ? 1.0 : diffs[diffs.size() / 2];
	std::printf("%s, frames 1-%d: toolbox detections >= 10 matched %.1f%% (%d), ours >= 10 "
		    "matched %.1f%% (%d), median relative score difference %.2f%%, %.1f ms/frame\n",
		    refFile, frames, 100 * refFound, nRef, 100 * oursFound, nOurs, 100 * median,
		    ms / frames);
	EXPECT_GT(nRef, 0);
	EXPECT_GE(refFound, minMatched);
	EXPECT_GE(oursFound, minMatched);
	EXPECT_LE(median, 0.03);
}

} // namespace

// Target (issue #2): 95% both ways (the misses left are NMS ties between neighbouring
// windows whose scores differ by less than the remaining score noise, docs/parity.md).
TEST(DetectionParity, Frames1To50Native) { runParity("dets_native.csv", 1.0, 0.95); }
TEST(DetectionParity, Frames1To50Resize2) { runParity("dets_up2x.csv", 2.0, 0.95); }
// Resize 2 inside the pyramid is the toolbox's nOctUp = 1 on the native frame.
TEST(DetectionParity, Frames1To50Resize2InPyramid)
{
	runParity("dets_octup1.csv", 2.0, 0.95, true);
}
