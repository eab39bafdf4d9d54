// SPDX-License-Identifier: BSD-2-Clause
// The generic-mode detector behind calped::Detector: input resize, pyramid, sliding
// window classifier over every level, NMS. Everything is allocated in init().
#pragma once

#include <calped/calibration.h>
#include <calped/detector.h>

#include <vector>

#include "detect/calibrated_plan.h"
#include "detect/dense_regions.h"
#include "detect/static_scene.h"
#include "detect/classifier.h"
#include "channels/frame_input.h"
#include "kernels.h"
#include "pyramid/pyramid.h"

namespace calped {

class DetectorImpl
{
public:
	Status init(const Model &model, const DetectorConfig &config);
	Status detect(const ImageView &image, Detections &out);

	DetectorConfig config;
	FrameStats stats;
	Pyramid pyramid;
	Classifier classifier;
	// Whether the pyramid is computed per frame in rectangles around what each pass reads
	// (set at init when it can be; tests turn it off to compare with the plan's fixed
	// bands).
	bool rectsPerFrame() const { return rectsPerFrame_; }
	void setRectsPerFrame(bool on) { rectsPerFrame_ = on && rectsPerFrameAllowed_; }

private:
	Status checkImage(const ImageView &image) const;
	// The box of window (row, col) of level l, in input-image pixels (no score).
	Detection boxOfWindow(const PyramidLevel &l, int row, int col) const;
	// Window hits of one level to boxes in input-image pixels, appended to candidates_.
	void addBoxes(int level, const kernels::WindowHit *hits, int count);
	Status initCalibrated();
	// Classify the listed windows of one level and keep the hits; returns ms spent.
	double classifyList(int level, const LevelChannels &channels, const uint32_t *windows,
			    size_t count);
	// Thesis 3.2: sparse grid and existing dense regions, new regions, their windows;
	// adds the classification time to ms.
	Status classifySparseDense(double &ms);
	// This frame's sparse windows (sparseList_): the plan's, or with the static-scene
	// gate only those whose box moves.
	void selectSparse();
	// Classify the first n windows of frameList_ on level i, adding the time to ms.
	Status classifyListed(int i, size_t n, double &ms);
	// Rectangle mode: the cells each level's windows read this pass (levelRects_), the
	// sparse grid's (with `sparse`) and those of regions firstRegion.., merged; then
	// the pyramid computes what they need (Pyramid::ensureRects).
	Status prepareRects(int firstRegion, bool sparse);
	// Windows of level i inside region r not evaluated yet, appended to frameList_.
	size_t collectDense(int i, const DenseRegion &r, size_t n);
	// Ground position and world height of the final detections.
	void addWorldCoordinates(Detection *boxes, int n) const;

	ModelParams params_;
	int maxWidth_ = 0, maxHeight_ = 0;
	// Calibrated mode (camera_ is also used in generic mode for world coordinates).
	bool hasCamera_ = false;
	CameraModel camera_;
	CalibratedPlan plan_;
	bool levelNeeded_[kMaxLevels] = {};
	RowBand levelRows_[kMaxLevels]; // calibrated: the rows of each level its windows read
	// Sparse-dense mode with a pyramid whose computed levels all come from the image
	// itself (placed levels): build() computes nothing, and each pass has the pyramid
	// computed in rectangles around what its windows read (Pyramid::ensureRects).
	bool rectsPerFrame_ = false, rectsPerFrameAllowed_ = false;
	int planLevels_ = 0;
	RowBand noRows_[kMaxLevels]; // build()'s bands when rectangles come later
	LevelRect levelRects_[kMaxLevels][Pyramid::kMaxRects];
	int levelRectCount_[kMaxLevels] = {};
	int rectLevels_[kMaxLevels * Pyramid::kMaxRects] = {};
	LevelRect rectList_[kMaxLevels * Pyramid::kMaxRects];
	// Static-scene gate of the sparse grid (StaticRejection::gateSparse): each sparse
	// window's box as cells of the static scene (plan order, level after level), and
	// this frame's sparse windows of each level.
	bool gateSparse_ = false;
	std::vector<StaticScene::CellRect> sparseCells_;
	std::vector<uint32_t> movingSparse_;
	const uint32_t *sparseList_[kMaxLevels] = {};
	size_t sparseListCount_[kMaxLevels] = {};
	DenseRegions regions_;
	std::vector<uint8_t> evaluated_; // per plan window grid: evaluated this frame
	std::vector<uint32_t> frameList_;
	// Camera frame -> RGB8 rows (docs/pixel-formats.md).
	FrameInput input_;
	// Static-scene rejection (DetectorConfig::staticRejection), when enabled.
	StaticScene static_;
	// Input resampling ("resize"): the factor the frame itself is resized by (1 when
	// the resize is done inside the pyramid, DetectorConfig::resizeInPyramid).
	double frameResize_ = 1.0;
	std::vector<uint8_t> resized_;
	std::vector<kernels::ResampleTap> resizeX_, resizeY_;
	std::vector<int32_t> resizeRow_;
	bool resizeTapsForMax_ = false; // resizeX_/Y_ hold the taps of maximum-size frames
	// Per-frame results.
	std::vector<kernels::WindowHit> hits_;
	std::vector<Detection> candidates_, sorted_;
	std::vector<int> order_;
	int candidateCount_ = 0;
};

} // namespace calped
