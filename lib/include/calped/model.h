// SPDX-License-Identifier: BSD-2-Clause
// The classifier model: Dollár's ACF options plus boosted trees whose thresholds are
// already in calped's fixed-point channel domain. Serialised as the blob in
// docs/model-format.md; the core reads it from memory (the tools read the files).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <calped/status.h>

namespace calped {

// Fixed-point format shared by every feature channel: value = q / 2^kChannelFracBits.
constexpr int kChannelFracBits = 14;
// Fixed-point format of leaf values and scores: value = q / 2^kScoreFracBits.
constexpr int kScoreFracBits = 16;
// Fixed-point format of LDCF filter weights: value = q / 2^kFilterFracBits. The toolbox's
// filters are unit-norm eigenvectors, so every weight lies in [-1, 1].
constexpr int kFilterFracBits = 15;

enum class NmsOverlapDenominator : uint32_t { Min = 0, Union = 1 };

// Whose approximate reciprocal instruction (rcpps) the colour conversion reproduces. The
// toolbox divides with it, and its results differ between CPU makers; on models without
// colour smoothing (Caltech+) that moves the toolbox's own orientation channels by 1-2% of
// their mean (docs/parity.md).
enum class ToolboxCpu : uint32_t {
	Intel = 0,   // Intel's published rule (the INRIA reference vectors' Xeon)
	AmdEpyc = 1, // measured on an AMD EPYC of family 26 (the Caltech+ and LDCF references)
};

// The options of a detector, named as in Dollár's toolbox (detector.opts).
struct ModelParams {
	// Window geometry, in pixels (height, width).
	float modelDsH = 100, modelDsW = 41;     // may be fractional (Caltech: 50 x 20.5)
	int32_t modelDsPadH = 128, modelDsPadW = 64;
	int32_t stride = 4;
	float cascThr = -1.0f; // soft cascade: a window stops once its score <= cascThr

	// Channels (pPyramid.pChns).
	int32_t shrink = 4;
	int32_t colorSmooth = 1;       // pColor.smooth: convTri radius before gradients
	int32_t gradNormRad = 5;       // pGradMag.normRad
	float gradNormConst = 0.005f;  // pGradMag.normConst
	int32_t gradColorChn = 0;      // pGradMag.colorChn: 0 = max over the three colour channels
	int32_t gradFull = 0;          // pGradMag.full: 0 = orientations in [0, pi)
	int32_t histBinSize = 4;       // pGradHist.binSize (the toolbox's empty means shrink)
	int32_t nOrients = 6;          // pGradHist.nOrients
	int32_t softBin = 0;           // pGradHist.softBin

	// Pyramid (pPyramid).
	int32_t nPerOct = 8, nOctUp = 0, nApprox = 7;
	float lambdas[3] = { 0.0f, 0.11579f, 0.11579f }; // colour, magnitude, histograms
	int32_t padH = 16, padW = 12;                    // pixels; /shrink cells each side
	float minDsH = 100, minDsW = 41;
	int32_t pyramidSmooth = 1;                       // convTri radius applied to every level

	// LDCF (opts.filters, Nam, Dollar and Han 2014): each of the ten channels is replicated
	// nFilters times, convolved with a filterSize x filterSize filter and resampled to half
	// size, so the trees see nFilters * 10 channels at twice the shrink. 0 and 0 for ACF.
	int32_t nFilters = 0;
	int32_t filterSize = 0;

	// Non-maximum suppression (pNms, type 'maxg').
	float nmsOverlap = 0.65f;
	NmsOverlapDenominator nmsOverlapDenominator = NmsOverlapDenominator::Min;

	// Not part of the model (never stored in the blob): which CPU's toolbox results the
	// channels reproduce. Intel unless set after loading.
	ToolboxCpu toolboxCpu = ToolboxCpu::Intel;
};

// Boosted trees stored node-major per tree: node k of tree t is at index t * nodesPerTree + k.
// Node 0 is the root. child[k] == 0 marks a leaf; otherwise the two children are
// child[k] (feature < threshold) and child[k] + 1 (feature >= threshold), as 0-based
// node indices within the tree (the toolbox's 1-based "child" minus one).
struct Model {
	std::string name; // e.g. "AcfInriaDetector"
	ModelParams params;
	int32_t nTrees = 0;
	int32_t nodesPerTree = 0;
	int32_t treeDepth = 0;         // maximum depth of any leaf
	std::vector<uint32_t> fids;    // feature index: row + rows * (col + cols * channel)
	std::vector<int32_t> thrs;     // threshold in channel fixed point; go left if q < thr
	std::vector<uint32_t> child;   // see above
	std::vector<int32_t> hs;       // leaf value in score fixed point
	// LDCF filter weights in Q15 (kFilterFracBits), as the toolbox stores them (applied by
	// convolution, i.e. flipped): weight (row y, column x) of filter j for channel c is
	// filters[((j * 10 + c) * filterSize + y) * filterSize + x]. Empty for ACF.
	std::vector<int32_t> filters;

	// Pixels per cell of the channels the trees read: shrink, doubled by LDCF's resampling.
	int32_t classifierShrink() const;
	// Channels the trees read: 10, times nFilters for LDCF (filtered channel c of filter j is
	// channel j * 10 + c, the toolbox's repmat order).
	int32_t classifierChannels() const;
	// Number of feature values in one window: (modelDsPadH / classifierShrink()) *
	// (modelDsPadW / classifierShrink()) * classifierChannels().
	int32_t featureCount() const;
};

// Parse and validate a blob. On failure `out` is left empty and the status names the problem.
Status loadModel(const uint8_t *data, size_t size, Model &out);

// Validate a model built in memory (the converter calls this before writing).
Status validateModel(const Model &model);

// Serialise a model to the blob format (for the converter and tests).
std::vector<uint8_t> serializeModel(const Model &model);

// Convert a toolbox float threshold to channel fixed point such that, for every integer q,
// (q < result) == (q / 2^kChannelFracBits < threshold).
int32_t thresholdToFixed(double threshold);

} // namespace calped
