// SPDX-License-Identifier: BSD-2-Clause
// The calibrated plan's world-height test (thesis 3.2) against the window geometry and the
// camera worked out here from their definitions: nothing below calls WindowBoxes or
// CameraModel::boxWorldHeight(), so a fault in either (or in how the plan uses them)
// makes the plan disagree with this test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <calped/calped.h>

#include "detect/detector_internals.h"
#include "search/calibrated_plan.h"
#include "pyramid/scales.h"
#include "synthetic.h"

using namespace calped;

namespace {

// A level camera `kEye` metres above the ground (world z up), looking along +y, focal
// length f, principal point (cx, cy), no distortion. A point at depth Y (world y) and
// height z is seen at row cy + f (kEye - z) / Y, so a person whose feet are on row vf
// (below the horizon, vf > cy) stands at Y = f kEye / (vf - cy), and the row vh of their
// head gives their height z = kEye (vf - vh) / (vf - cy), whatever the column.
constexpr double kEye = 2.0;

CameraModel levelCamera(double f, double cx, double cy)
{
	Eigen::Matrix3d K;
	K << f, 0, cx, 0, f, cy, 0, 0, 1;
	Eigen::Matrix3d R;
	R << 1, 0, 0, 0, 0, -1, 0, 1, 0; // camera x = world x, camera y = -world z, camera z = world y
	const Eigen::Vector3d t(0, kEye, 0);
	CameraModel camera;
	const Status st = CameraModel::fromPinhole(K, R, t, LengthUnit::Metre, camera);
	EXPECT_TRUE(st.ok()) << st.message();
	return camera;
}

// World height of a box standing on row footRow with its top on row headRow (NaN when
// the feet are not below the horizon row cy).
double heightFromRows(double cy, double footRow, double headRow)
{
	if (!(footRow > cy))
		return NAN;
	return kEye * (footRow - headRow) / (footRow - cy);
}

// The box of window (row, col) of level l, in pixels of the frame before the input resize,
// from the model's geometry (calped/model.h, the toolbox's acfDetect):
//  - the level is the frame resized by `resize`, then by scaleW x scaleH (its rounded
//    size over the resized frame's), and padded by padW, padH pixels on each side
//    (padW / shrink, padH / shrink channel cells);
//  - window (row, col) is the modelDsPadW x modelDsPadH pixel window whose top-left corner
//    is at (col * stride, row * stride) pixels of the padded level;
//  - the person's box is the modelDsW x modelDsH rectangle centred in the window, its size
//    in the frame taken at the level's nominal scale (as the toolbox does).
struct Box {
	double x, y, w, h;
};
Box boxFromDefinitions(const ModelParams &p, const PyramidLevel &l, double resize, int row,
		       int col)
{
	const double paddedX = col * p.stride + (p.modelDsPadW - p.modelDsW) / 2.0;
	const double paddedY = row * p.stride + (p.modelDsPadH - p.modelDsH) / 2.0;
	Box b;
	b.x = (paddedX - p.padW) / l.scaleW / resize;
	b.y = (paddedY - p.padH) / l.scaleH / resize;
	b.w = p.modelDsW / l.scale / resize;
	b.h = p.modelDsH / l.scale / resize;
	return b;
}

} // namespace

TEST(CalibratedPlan, EveryPlannedWindowHasAPlausibleHeight)
{
	const double f = 600, cx = 320, cy = 120, minHeight = 1.4, maxHeight = 2.2;
	const CameraModel camera = levelCamera(f, cx, cy);

	// The closed form above, checked once through the camera's own projection: a 1.75 m
	// person 6 m away and 1.5 m to the side.
	{
		const Eigen::Vector2d foot = camera.worldToPixel(Eigen::Vector3d(1.5, 6.0, 0.0));
		const Eigen::Vector2d head = camera.worldToPixel(Eigen::Vector3d(1.5, 6.0, 1.75));
		EXPECT_NEAR(foot.x(), head.x(), 1e-9);
		EXPECT_NEAR(foot.y(), cy + f * kEye / 6.0, 1e-9);
		EXPECT_NEAR(heightFromRows(cy, foot.y(), head.y()), 1.75, 1e-9);
	}

	DetectorConfig cfg;
	cfg.maxWidth = 640;
	cfg.maxHeight = 480;
	cfg.method = DetectionMethod::Calibrated;
	cfg.camera = &camera;
	std::unique_ptr<Detector> det;
	const Status st = Detector::create(test::randomModel(1), cfg, det);
	ASSERT_TRUE(st.ok()) << st.message();
	const Classifier &classifier = DetectorInternals::of(*det).classifier;

	const ModelParams p; // test::randomModel's: the INRIA geometry
	ASSERT_EQ(p.padH % p.shrink, 0);
	ASSERT_EQ(p.padW % p.shrink, 0);
	const int padCellsH = p.padH / p.shrink, padCellsW = p.padW / p.shrink;

	// The frame itself (resize 1) and the frame enlarged 2x before the pyramid (resize 2,
	// the main job's --resize 2): the boxes are then half the size in the frame.
	for (const double resize : { 1.0, 2.0 }) {
		ScaleList scales;
		ASSERT_TRUE(computeScales(p, int(480 * resize), int(640 * resize), scales));
		ASSERT_GT(scales.count, 0);
		CalibratedPlan plan;
		ASSERT_TRUE(plan.build(camera, p, scales, WindowBoxes(p, resize), padCellsH, padCellsW, classifier,
				       minHeight, maxHeight)
				    .ok());
		size_t planned = 0, expected = 0, all = 0, borderline = 0;
		int levels = 0;
		for (int i = 0; i < scales.count; i++) {
			const PyramidLevel &l = scales.levels[i];
			// Windows that fit in the padded level, stepping `stride` pixels.
			const int paddedH = (l.height + 2 * padCellsH) * p.shrink;
			const int paddedW = (l.width + 2 * padCellsW) * p.shrink;
			const int rows = paddedH >= p.modelDsPadH ? (paddedH - p.modelDsPadH) / p.stride + 1 : 0;
			const int cols = paddedW >= p.modelDsPadW ? (paddedW - p.modelDsPadW) / p.stride + 1 : 0;
			ASSERT_EQ(plan.rows(i), rows) << "resize " << resize << " level " << i;
			ASSERT_EQ(plan.cols(i), cols) << "resize " << resize << " level " << i;

			std::vector<uint8_t> listed(size_t(rows) * cols, 0);
			for (size_t k = 0; k < plan.windowCount(i); k++) {
				const uint32_t w = plan.windows(i)[k];
				const int r = int(w >> 16), c = int(w & 0xFFFF);
				ASSERT_TRUE(r < rows && c < cols) << "level " << i << " window " << r << "," << c;
				listed[size_t(r) * cols + c] = 1;
			}
			for (int r = 0; r < rows; r++)
				for (int c = 0; c < cols; c++) {
					const Box b = boxFromDefinitions(p, l, resize, r, c);
					const double h = heightFromRows(cy, b.y + b.h, b.y);
					const bool inPlan = plan.plausible(i, r, c);
					ASSERT_EQ(inPlan, listed[size_t(r) * cols + c] == 1)
						<< "level " << i << " window " << r << "," << c;
					// Heights within rounding of a bound may go either way.
					if (std::fabs(h - minHeight) < 1e-9 || std::fabs(h - maxHeight) < 1e-9) {
						borderline++;
						continue;
					}
					const bool plausible = h >= minHeight && h <= maxHeight;
					expected += plausible ? 1 : 0;
					ASSERT_EQ(plausible, inPlan)
						<< "resize " << resize << " level " << i << " (scale " << l.scale
						<< ") window " << r << "," << c << ": box " << b.x << "," << b.y
						<< " " << b.w << "x" << b.h << ", world height " << h;
				}
			// Each column's plausible row range is tight: its ends are plausible windows and
			// nothing plausible lies outside it.
			for (int c = 0; c < cols; c++) {
				int first, last;
				plan.plausibleRows(i, c, first, last);
				for (int r = 0; r < rows; r++)
					if (r < first || r > last) {
						ASSERT_FALSE(plan.plausible(i, r, c)) << "level " << i << " " << r << "," << c;
					}
				if (first <= last) {
					EXPECT_TRUE(plan.plausible(i, first, c));
					EXPECT_TRUE(plan.plausible(i, last, c));
				}
			}
			planned += plan.windowCount(i);
			all += size_t(rows) * cols;
			levels += plan.levelNeeded(i) ? 1 : 0;
		}
		std::printf("resize %g: %d of %d levels, %zu of %zu windows planned (%zu expected, %zu "
			    "within 1e-9 m of a bound)\n",
			    resize, levels, scales.count, planned, all, expected, borderline);
		EXPECT_GT(planned, 0u);
		EXPECT_LT(planned, all / 2);
	}
}
