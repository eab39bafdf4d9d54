// SPDX-License-Identifier: BSD-2-Clause
#include "parity_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "test_data.h"

namespace calped {
namespace test {

namespace {

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

} // namespace

std::map<int, std::vector<Box>> readDetections(const std::string &path)
{
	std::map<int, std::vector<Box>> out;
	std::ifstream f(path);
	std::string line;
	while (std::getline(f, line)) {
		if (line.empty() || line[0] == '#')
			continue;
		std::replace(line.begin(), line.end(), ',', ' ');
		std::istringstream s(line);
		int frame;
		Box b;
		if (s >> frame >> b.x >> b.y >> b.w >> b.h >> b.score)
			out[frame].push_back(b);
	}
	return out;
}

void expectDetectionParity(const std::string &modelBlob, const std::string &refPath, int frames,
			   double resize, ResizeAt where, double minMatched, ToolboxCpu cpu)
{
	std::vector<uint8_t> blob;
	ASSERT_TRUE(readFile(modelBlob, blob)) << modelBlob;
	Model model;
	Status st = loadModel(blob.data(), blob.size(), model);
	ASSERT_TRUE(st.ok()) << st.message();
	model.params.toolboxCpu = cpu;
	DetectorConfig cfg;
	cfg.maxWidth = 768;
	cfg.maxHeight = 576;
	cfg.resize = resize;
	cfg.resizeAt = where;
	std::unique_ptr<Detector> det;
	st = Detector::create(model, cfg, det);
	ASSERT_TRUE(st.ok()) << st.message();

	// CALPED_PARITY_FRAMES shortens the run (by hand: nothing in the test command sets it).
	if (const char *env = std::getenv("CALPED_PARITY_FRAMES"))
		frames = std::clamp(std::atoi(env), 1, frames);
	auto ref = readDetections(refPath);
	for (auto it = ref.begin(); it != ref.end();)
		it = it->first > frames ? ref.erase(it) : std::next(it);
	std::map<int, std::vector<Box>> ours;
	double ms = 0;
	for (int k = 1; k <= frames; k++) {
		RgbImage img;
		ASSERT_TRUE(loadRgb(petsFrame(k), img));
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
	const std::string name = refPath.substr(refPath.find_last_of('/') + 1);
	std::printf("%s (%s), frames 1-%d: toolbox detections >= 10 matched %.1f%% (%d), ours >= 10 "
		    "matched %.1f%% (%d), median relative score difference %.2f%%, %.1f ms/frame\n",
		    name.c_str(), model.name.c_str(), frames, 100 * refFound, nRef, 100 * oursFound,
		    nOurs, 100 * median, ms / frames);
	EXPECT_GT(nRef, 0);
	EXPECT_GE(refFound, minMatched);
	EXPECT_GE(oursFound, minMatched);
	EXPECT_LE(median, 0.03);
}

size_t expectLevelWithinTolerance(const LevelChannels &lc, int channels, const std::vector<float> &ref,
				  size_t offset, const char *what, double orientMean)
{
	const int h = lc.paddedHeight, w = lc.paddedWidth;
	const size_t n = size_t(h) * w * channels;
	EXPECT_LE(offset + n, ref.size()) << what;
	if (offset + n > ref.size())
		return n;
	for (int c = 0; c < channels; c++) {
		std::vector<float> ours(size_t(h) * w), theirs(size_t(h) * w);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				ours[size_t(y) * w + x] = lc.data[c * lc.planeStride + y * lc.rowStride + x] / 16384.0f;
				theirs[size_t(y) * w + x] = ref[offset + y + size_t(h) * x + size_t(h) * w * c];
			}
		const DiffStats d = compare(ours.data(), theirs.data(), ours.size());
		const double meanPct = 100 * d.meanAbs / d.meanA, p99Pct = 100 * d.p99Abs / d.maxA;
		std::printf("%s channel %2d: mean |diff| %.3f%% of mean, p99 %.3f%% of max\n", what, c,
			    meanPct, p99Pct);
		const double meanTolerance = (c % kChannelCount) >= 4 ? orientMean : 0.01;
		EXPECT_LE(d.meanAbs, meanTolerance * d.meanA) << what << " channel " << c;
		EXPECT_LE(d.p99Abs, 0.05 * d.maxA) << what << " channel " << c;
	}
	return n;
}

Frame1 toolboxPyramidFrame1(const char *name, ToolboxFrame1 &out)
{
	const std::string shared = sharedDir();
	const std::string frame = petsFrame(1);
	const std::string path = toolboxModelBlob(name);
	std::vector<uint8_t> blob;
	if (shared.empty() || frame.empty() || path.empty() || !readFile(path, blob) ||
	    !loadModel(blob.data(), blob.size(), out.model).ok())
		return Frame1::Absent;
	RgbImage img;
	if (!loadRgb(frame, img)) {
		ADD_FAILURE() << "cannot decode " << frame;
		return Frame1::Failed;
	}
	out.reference = readFloats(shared + "/reference/dollar-toolbox-pets/" + name + "/pyr_frame1_levels1-2.bin");
	if (out.reference.empty()) {
		ADD_FAILURE() << "no pyr_frame1_levels1-2.bin for " << name;
		return Frame1::Failed;
	}
	out.model.params.toolboxCpu = ToolboxCpu::AmdEpyc;
	Status st = out.pyramid.init(out.model.params, img.width, img.height);
	if (st.ok())
		st = out.pyramid.compute(img.pixels.data(), 3 * img.width, img.width, img.height);
	if (!st.ok()) {
		ADD_FAILURE() << name << ": " << st.message();
		return Frame1::Failed;
	}
	return Frame1::Ready;
}

} // namespace test
} // namespace calped
