// SPDX-License-Identifier: BSD-2-Clause
// The calibrated method with LDCF: every window it classifies, in rectangles of placed
// levels (each grown by what the filter stage reads), in the plan's bands, or in one pass over
// every plausible window, scores exactly what the same window scores on the whole level
// computed and filtered in full.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <tuple>

#include <calped/calped.h>

#include "detect/detector_internals.h"
#include "pyramid/ldcf_filter.h"
#include "search/window_boxes.h"
#include "synthetic.h"

using namespace calped;

namespace {

using BoxKey = std::tuple<float, float, float, float>;

// Every window of every level of `pyr` (computed whole and filtered whole, by `filter`:
// not on demand), by its box: its score.
std::map<BoxKey, float> fullLevelScores(Pyramid &pyr, LdcfFilter &filter, const Classifier &classifier,
					const ModelParams &params)
{
	std::map<BoxKey, float> out;
	const WindowBoxes boxes(params, 1.0);
	std::vector<kernels::WindowHit> hits(1 << 20);
	for (int i = 0; i < pyr.scales().count; i++) {
		const PyramidLevel &l = pyr.scales().levels[i];
		uint64_t windows = 0;
		const LevelChannels filtered = filter.apply(pyr.prepare(i));
		EXPECT_EQ(filtered.onDemand, nullptr);
		const uint64_t n = classifier.scan(filtered, hits.data(), hits.size(), &windows);
		EXPECT_EQ(n, windows) << "level " << i << ": every window passes the cascade";
		for (uint64_t k = 0; k < std::min<uint64_t>(n, hits.size()); k++) {
			const WindowBox b = boxes.box(l, hits[k].row, hits[k].col);
			out[BoxKey(float(b.x), float(b.y), float(b.w), float(b.h))] =
				float(hits[k].score / double(1 << kScoreFracBits));
		}
	}
	return out;
}

} // namespace

TEST(LdcfCalibrated, WindowScoresEqualTheFullLevels)
{
	const Model model = test::randomLdcfModel(5, 128);
	CameraModel camera;
	ASSERT_TRUE(test::syntheticCamera(camera));
	const int w = 320, h = 240;
	DetectorConfig cfg;
	cfg.maxWidth = w;
	cfg.maxHeight = h;
	cfg.resize = 2.0;
	cfg.resizeAt = ResizeAt::Pyramid;
	cfg.method = DetectionMethod::Calibrated;
	cfg.camera = &camera;
	cfg.cascadeThreshold = -1000.0f; // every window is a candidate, with its score
	cfg.nms = false;
	cfg.calibrated = CalibratedSettings();
	cfg.calibrated->levels = PyramidLevels::Placed;
	cfg.calibrated->boxVoting = false;
	// Rectangles around each pass's windows; the plan's bands demanded once a frame
	// (prepared in the rows and columns the windows read); one pass over every plausible
	// window (levels prepared whole, exact in the plan's bands only).
	std::unique_ptr<Detector> det, bands, every;
	Status st = Detector::create(model, cfg, det);
	ASSERT_TRUE(st.ok()) << st.message();
	ASSERT_TRUE(Detector::create(model, cfg, bands).ok());
	DetectorImpl &impl = DetectorInternals::of(*det);
	ASSERT_TRUE(impl.calibratedSearch.rectsPerFrame());
	DetectorInternals::of(*bands).calibratedSearch.setRectsPerFrame(false);
	cfg.calibrated->sparseDense = false;
	ASSERT_TRUE(Detector::create(model, cfg, every).ok());

	// The reference: the same placed levels, computed whole, filtered whole (the windows'
	// scores read each filtered cell on demand).
	ScaleList placed;
	ASSERT_TRUE(impl.pyramid.scalesFor(w, h, placed).ok());
	int source[kMaxLevels];
	for (int i = 0; i < placed.count; i++)
		source[i] = placed.levels[i].source;
	Pyramid full;
	ASSERT_TRUE(full.init(model.params, w, h, kernels::bestKernels(), cfg.resize).ok());
	ASSERT_TRUE(full.placeLevels(source, placed.count).ok());
	LdcfFilter wholeFilter;

	size_t compared = 0;
	for (uint32_t seed = 0; seed < 2; seed++) {
		const std::vector<uint8_t> frame = test::randomImage(seed, w, h);
		ASSERT_TRUE(full.compute(frame.data(), 3 * w, w, h).ok());
		if (seed == 0) {
			// With the detector's strides, so the trees' offsets hold for both.
			const ptrdiff_t rowStride = impl.pyramid.classifierRowStride();
			const ptrdiff_t rows = impl.pyramid.classifierPlaneStride() / rowStride;
			ASSERT_TRUE(wholeFilter.init(model, int(2 * rows), int(2 * rowStride)).ok());
			ASSERT_EQ(wholeFilter.rowStride(), rowStride);
			ASSERT_EQ(wholeFilter.planeStride(), impl.pyramid.classifierPlaneStride());
		}
		const std::map<BoxKey, float> want = fullLevelScores(full, wholeFilter, impl.classifier, model.params);
		for (Detector *which : { det.get(), bands.get(), every.get() }) {
			const char *mode = which == det.get() ? "rectangles" : which == bands.get() ? "bands" : "every window";
			Detections d;
			st = which->detect(ImageView::rgb8(frame.data(), w, h), d);
			ASSERT_TRUE(st.ok()) << st.message();
			ASSERT_EQ(which->lastStats().droppedWindows, 0u);
			ASSERT_EQ(uint64_t(d.count), which->lastStats().windows);
			ASSERT_LT(size_t(d.count), want.size()) << "the calibrated method classifies fewer windows";
			for (const Detection &b : d) {
				const auto it = want.find(BoxKey(b.x, b.y, b.w, b.h));
				ASSERT_NE(it, want.end()) << mode << ": a window the full levels do not have: " << b.x
							  << "," << b.y;
				ASSERT_EQ(b.score, it->second) << mode << ", frame " << seed << " box " << b.x << ","
							       << b.y << " " << b.w << "x" << b.h;
				compared++;
			}
		}
	}
	std::printf("LDCF calibrated, placed levels in %ld rectangles, in bands, every plausible window: %zu "
		    "window scores over 2 frames equal the full levels'\n",
		    impl.pyramid.rectsComputed, compared);
	EXPECT_GT(impl.pyramid.rectsComputed, 0);
	EXPECT_GT(compared, 1000u);
}

// What the calibrated plan grows its rectangles by covers what the half-size resampling
// really reads, for every level size (odd ones spread an output over three samples).
TEST(LdcfCalibrated, CellsReadCoverTheResamplingTaps)
{
	std::vector<kernels::ResampleTap> taps(512);
	for (int n = 1; n < 800; n++) {
		const int m = (n + 1) / 2;
		ASSERT_TRUE(kernels::buildResampleTaps(n, m, 1.0, taps.data()));
		for (int o = 0; o < m; o++) {
			const CellRange read = sourceRows(taps.data(), CellRange{ o, o + 1 });
			// Filter size 1 (no reach) and no padding: the resampling alone.
			EXPECT_TRUE(LdcfFilter::levelCellsRead(CellRange{ o, o + 1 }, 1, 0, n).contains(read))
				<< n << " samples, output " << o << " reads " << read.begin << ".." << read.end;
			// With the 5x5 filter and 7 cells of padding: two more each side, 7 fewer.
			const CellRange grown = LdcfFilter::levelCellsRead(CellRange{ o, o + 1 }, 5, 7, n);
			EXPECT_TRUE(grown.contains(CellRange{ read.begin - 2 - 7, read.end + 2 - 7 }.clipped(n)));
		}
	}
}
