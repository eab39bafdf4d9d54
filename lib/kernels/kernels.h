// SPDX-License-Identifier: BSD-2-Clause
// Signatures of the hot per-frame kernels. Each kernel has a plain scalar reference in
// kernels/ref/ (the specification: rounding and saturation are defined there) and may
// have SIMD versions that must produce bit-identical output (tests compare them).
//
// Number formats (docs/channels.md): every channel plane holds uint16 values
// q = round(value * 2^14) ("Q14"), saturated to 65535.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped {
namespace kernels {

constexpr int kQ = 14;            // channel fraction bits
constexpr int kOne = 1 << kQ;     // 1.0 in channel fixed point
// The full-resolution LUV image keeps two more bits: gradients of the smoothed colour
// planes are small differences, and rounding them at Q14 biases weak magnitudes.
constexpr int kLuvQ = 16;
// u and v multiply the ratios x / d and y / d by 52 and 117 (d = x + 15 y + 3 z), so the
// ratios keep four more bits than the result: Q16 ratios moved the orientation channels
// by 0.8 points of their mean.
constexpr int kLuvRatioQ = 20;
// Orientations are in units of pi/nOrients with this many fraction bits.
constexpr int kOrientQ = 10;
// Steps of the cosine in the toolbox's acos table (its gradMag indexes acos(i / 10000)).
constexpr int kCosSteps = 10000;

// ---- colour: RGB8 -> LUV (Q16), the toolbox's rgbConvert(I, 'luv') -------------------
// Whose approximate reciprocal (rcpps) the colour conversion reproduces: the toolbox
// divides with it, and its results differ between CPU makers (docs/channels.md).
enum class RcpRule {
	Intel,   // the published rule of Intel's CPUs (the INRIA reference's Xeon)
	AmdEpyc, // measured on an AMD EPYC of family 26 (the Caltech+ and LDCF references)
};

struct LuvTables {
	// x, y, z = c[0] * r + c[1] * g + c[2] * b in Q28 (the toolbox's matrix / 255). The L
	// table is indexed by floor(y * 1024), so y needs to be exact well beyond 2^-10: a
	// pixel whose index flips moves L by a whole table step.
	int32_t cx[3], cy[3], cz[3];
	// L/270 in Q16 indexed by floor(y * 1024) (the toolbox's 1025-entry cube-root table).
	uint16_t l[1025 + 39];
	// 2^28 / m for normalised mantissas m in [4096, 8192), as the toolbox's rcpps gives it
	// (12 fraction bits, docs/channels.md): Intel's depends on the top 11 bits of m's
	// fraction, AMD's on all 12.
	uint32_t rcp[4096];
	int32_t un13, vn13; // 13 * u'n, 13 * v'n in Q20 (kLuvRatioQ)
	int32_t minu, minv; // the toolbox's offsets -88/270, -134/270 in Q16
};
void buildLuvTables(LuvTables &t, RcpRule rule = RcpRule::Intel);

using RgbToLuvFn = void (*)(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride,
			    int width, int height, uint16_t *l, uint16_t *u, uint16_t *v,
			    ptrdiff_t stride);
void rgbToLuv_ref(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		  int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride);
void rgbToLuv_avx2(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		   int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride);

// ---- resampling (the toolbox's imResampleMex) ------------------------------------------
// Separable linear resampling: output index o takes taps[o].count source samples
// starting at taps[o].first with Q14 weights (area weights when shrinking, bilinear
// when enlarging, exactly as the toolbox builds them).
constexpr int kMaxTaps = 12;
struct ResampleTap {
	int32_t first;
	int32_t count;
	int32_t weight[kMaxTaps];
};

// Taps for resampling n source samples to m, emulating the toolbox's resampleCoef in
// single precision; weights sum to round(gain * 2^14). Returns false if a tap count
// would exceed kMaxTaps (shrinking by more than about 10x).
bool buildResampleTaps(int n, int m, double gain, ResampleTap *taps);

// uint8 interleaved RGB -> uint8 interleaved RGB (input "resize"). rowTmp holds
// 3 * srcWidth int32. Rounding reproduces the toolbox's (uchar)(v + .5) after its
// 1/(1+1e-6) factor, i.e. exact halves round down.
void resampleRgb8_ref(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		      uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		      const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp);

void resampleRgb8_opt(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		      uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		      const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp);

// One uint16 plane -> one plane of the same fixed-point format. yTaps' weights may include a gain (the power-law
// ratio of approximated levels). tmp holds srcHeight rows of dstWidth uint16.
void resamplePlane_ref(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
		       ptrdiff_t tmpStride);
void resamplePlane_opt(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
		       ptrdiff_t tmpStride);

// Several planes of one size resampled with the same xTaps (the channels of one pyramid
// level): SIMD versions plan the row pass once for all of them. Each plane has its own
// strides and yTaps (the channel types' gains differ); tmp is shared.
struct PlaneJob {
	const uint16_t *src;
	ptrdiff_t srcStride;
	uint16_t *dst;
	ptrdiff_t dstStride;
	const ResampleTap *yTaps;
};
using ResamplePlaneFn = decltype(&resamplePlane_ref);
// The plain form: one plane after another with a single-plane kernel.
template <ResamplePlaneFn plane>
void resampleEachPlane(const PlaneJob *jobs, int count, int srcWidth, int srcHeight, int dstWidth,
		       int dstHeight, const ResampleTap *xTaps, uint16_t *tmp, ptrdiff_t tmpStride)
{
	for (int i = 0; i < count; i++)
		plane(jobs[i].src, jobs[i].srcStride, srcWidth, srcHeight, jobs[i].dst, jobs[i].dstStride,
		      dstWidth, dstHeight, xTaps, jobs[i].yTaps, tmp, tmpStride);
}
void resamplePlanes_ref(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			ptrdiff_t tmpStride);
void resamplePlanes_opt(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			ptrdiff_t tmpStride);

// ---- smoothing ---------------------------------------------------------------------------
// convTri with radius 1: [1 2 1]/4 in both directions, borders replicated. dst may not
// alias src. rowTmp holds width uint32.
void smoothTri1_ref(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		    ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp);
void smoothTri1_opt(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		    ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp);

// ---- gradients ---------------------------------------------------------------------------
struct GradientTables {
	// Square root / reciprocal square root as the toolbox computes them (rcpps(rsqrtps(m))
	// and rsqrtps(m), docs/channels.md), indexed by a 12-bit mantissa (normalizeEven).
	uint16_t sqrtQ8[4096];   // ~sqrt(m) * 2^8
	uint32_t rsqrtQ20[4096]; // ~2^20 / sqrt(m), exact
	// Both in one entry, rsqrtQ20[m] | sqrtQ8[m] << 32: one read for both where tables
	// are read lane by lane (NEON has no gather).
	uint64_t roots[4096];
	// Orientation (in units of pi/nOrients, kOrientQ fraction bits) from the cosine as the
	// toolbox indexes its acos table: c = cos * kCosSteps truncated toward zero.
	uint16_t fromCos[2 * kCosSteps + 1]; // index c + kCosSteps
	int nOrients;
	// Reciprocal for the normalisation M / (S + c): 1296 * 2^16 / (m + .5), m in [2048, 4096).
	uint32_t normRcp[2048];
	uint32_t normConst; // c * 2^16 * (normRad+1)^4, added to the smoothed magnitude sum
};
void buildGradientTables(GradientTables &t, int nOrients, int normRad, double normConst);

// Gradient of three smoothed Q16 colour planes (max magnitude over channels, as the
// toolbox's gradMag with colorChn 0): magnitude in Q16, saturated at 65535, and
// orientation o in units of pi/nOrients with kOrientQ fraction bits
// (0 <= o < nOrients << kOrientQ). Each doubled
// derivative saturates at +-46340 so squared magnitudes fit 32 bits.
void gradMagOrient_ref(const GradientTables &t, const uint16_t *const planes[3],
		       ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
		       ptrdiff_t outStride, int32_t *scratch);
// scratch: 4 * width int32.
void gradMagOrient_avx2(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *scratch);
void gradMagOrient_opt(const GradientTables &t, const uint16_t *const planes[3],
		       ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
		       ptrdiff_t outStride, int32_t *scratch);

// Triangle filter of radius r (the toolbox's convTri, symmetric borders) without the
// final division: out = sum of weights * in, weights summing to (r+1)^4. scratch holds
// triSumScratchSize(width, height, r) uint32.
inline size_t triSumScratchSize(int width, int height, int r)
{
	return size_t(width) * height + size_t(r + 6) * (width + 2 * r) + height;
}
void triSumR_ref(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		 int width, int height, int r, uint32_t *scratch);
void triSumR_opt(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		 int width, int height, int r, uint32_t *scratch);

// mag / (smoothedSum / (r+1)^4 + c): Q16 magnitude in, Q14 channel out, in place
// (the toolbox's gradMagNorm). smoothedSum + normConst must fit 32 bits.
void normalizeMag_ref(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		      const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height);
void normalizeMag_avx2(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		       const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height);

// ---- aggregation -------------------------------------------------------------------------
// 4x4 block average (the toolbox's shrink by imResampleMex): dst is width/4 x height/4,
// divided by a further 2^extraShift (to turn Q16 colour into Q14 channels). scratch
// holds width uint32.
void shrink4_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void shrink4_opt(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void shrink4_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);

// Orientation histograms over 4x4 cells (gradHist, binSize 4): nOrients planes of
// width/4 x height/4. softBin >= 0 splits each pixel between its two nearest
// orientations (linear in angle); softBin < 0 gives it wholly to the nearest one.
// scratch holds nOrients * width uint32.
void gradHist4_ref(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch);
void gradHist4_opt(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch);
void gradHist4_avx2(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch);

// 2x2 block average (shrink 2): dst is width/2 x height/2, divided by a further
// 2^extraShift. No scratch needed (the argument keeps shrink4's signature).
void shrink2_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);

// Orientation histograms over 2x2 cells (gradHist, binSize 2): nOrients planes of
// width/2 x height/2. interpolate (softBin >= 0) splits each pixel between its two
// nearest orientations; spatial (softBin odd) also spreads it over the four nearest cells
// with the toolbox's bilinear weights (3/4 and 1/4 each way) and scales the border cells
// by 8/7, as its gradHist does. scratch holds 2 * nOrients * width uint32 (8-byte aligned).
void gradHist2_ref(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch);
// Optimised versions (opt/hist2_body.h; x86/aggregate2_avx2.cpp, arm/aggregate2_neon.cpp).
void shrink2_opt(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		 uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void gradHist2_opt(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		   int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		   ptrdiff_t histStride, uint32_t *scratch);
void shrink2_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void gradHist2_avx2(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch);

// ---- LDCF (locally decorrelated channels) ----------------------------------------------
// Filtered channels are signed and reach beyond Q14's [0, 4) (LdcfInriaDetector's
// thresholds go to 4.44): they are kept as q + kLdcfBias with q = round(value * 2^kLdcfQ),
// saturated to uint16, i.e. [-8, 8) in steps of 1/4096. Tree thresholds are moved to the
// same format (a Q14 threshold T becomes ceil(T / 4) + kLdcfBias, exactly the same splits).
constexpr int kLdcfQ = 12;
constexpr int kLdcfBias = 1 << 15;
// Matlab's conv2(src, filter, 'same') (a convolution: the filter flipped), zero outside the
// plane: a Q14 channel plane of width x height and a size x size Q15 filter (row-major,
// size odd) into a biased Q12 plane of the same size. Resampling it afterwards with the
// resample kernels keeps the bias exact (their weights sum to 2^14).
void ldcfFilter_ref(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		    const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride);
// SIMD versions: 5x5 filters with int16 weights vectorised (opt/ldcf_body.h), others
// by the reference.
void ldcfFilter_avx2(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		     const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride);
void ldcfFilter_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		     const int32_t *filter, int size, uint16_t *dst, ptrdiff_t dstStride);
// LDCF's filter as ldcfCell takes it: the size x size Q15 weights (|w| <= 2^15) and, when
// the vector versions can take them (5 x 5, every weight an int16), the same weights laid
// out by packLdcfCellFilter; null otherwise, and the vector versions run the reference.
struct LdcfCellFilter {
	const int32_t *weights;
	int size;
	const int16_t *packed;
};
// The layout: for filter row a (0..4) and output column j (0..3) of a block of adjacent
// full-size cells, eight int16 lanes that meet the samples from two columns before the
// block's first: lane j + 4 - b holds tap (a, b), the rest 0 (index (a * 4 + j) * 8 + lane).
constexpr int kLdcfPackedCount = 5 * 4 * 8;
// False, writing nothing, when the filter is not 5 x 5 or a weight is not an int16.
bool packLdcfCellFilter(const int32_t *weights, int size, int16_t *packed);
// One cell of a filtered, half-size plane on its own (LdcfFilter::onDemand): what
// ldcfFilter over the whole width x height plane and then resamplePlane with these taps
// give at that output. The filter at each full-size cell the taps read (rows yTap.first..,
// columns xTap.first..), rounded as ldcfFilter_ref rounds it; then the taps along the row
// and down the column, each rounded as resamplePlane_ref rounds them.
uint16_t ldcfCell_ref(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		      const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap);
// SIMD versions: packed filters, cells whose filter reads lie inside the plane and whose
// taps read at most four columns and four rows (opt/ldcf_body.h); others by the
// reference. All the full-size values a cell needs come from one load of each plane row
// they read.
uint16_t ldcfCell_avx2(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap);
uint16_t ldcfCell_neon(const uint16_t *plane, ptrdiff_t stride, int width, int height,
		       const LdcfCellFilter &filter, const ResampleTap &xTap, const ResampleTap &yTap);

// ---- boosted trees over sliding windows ------------------------------------------------
// A complete depth-2 tree with its feature offsets resolved for the level layout:
// node 0 tests off[0] < thr[0]; then node 1 (left) or node 2 (right); leaves 0..3 are
// left-left, left-right, right-left, right-right.
struct Depth2Tree {
	uint32_t off[3];
	int32_t thr[3];
	int32_t leaf[4];
};

// A general tree node: leaf when child == 0, else children child and child + 1.
struct TreeNode {
	uint32_t off;
	int32_t thr;
	uint32_t child;
	int32_t leaf;
};

// A window that passed the soft cascade: its origin (in cells) and score (Q16).
struct WindowHit {
	int32_t row, col;
	int32_t score;
};

// A window scoring h is a hit when it passed the cascade: counted in `passed`, written to
// hits while there is room (the caller sees how many it lost).
inline void keepHit(int32_t h, int32_t cascThr, int row, int col, WindowHit *hits, uint64_t capacity,
		    uint64_t &passed)
{
	if (h > cascThr) {
		if (passed < capacity)
			hits[passed] = { row, col, h };
		passed++;
	}
}

// Evaluate every window whose origin is at (r * step, c * step) cells for r < rows,
// c < cols, in the toolbox's order (columns outer). A window stops as soon as its
// running score is <= cascThr and is kept if it ends above it. Returns the number of
// windows that passed; only the first `capacity` are written.
uint64_t scanDepth2_ref(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
			const Depth2Tree *trees, int nTrees, int32_t cascThr, WindowHit *hits,
			uint64_t capacity);
uint64_t scanTrees_ref(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
		       const TreeNode *nodes, int nTrees, int nodesPerTree, int32_t cascThr,
		       WindowHit *hits, uint64_t capacity);
// The same over a list of windows, each packed as row << 16 | column (calibrated mode).
uint64_t scanDepth2List_ref(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			    size_t count, int step, const Depth2Tree *trees, int nTrees,
			    int32_t cascThr, WindowHit *hits, uint64_t capacity);
uint64_t scanTreesList_ref(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			   size_t count, int step, const TreeNode *nodes, int nTrees,
			   int nodesPerTree, int32_t cascThr, WindowHit *hits, uint64_t capacity);
// Depth-2 trees several windows at a time (trees_batch.h): eight with AVX2, four with NEON
// (window lists only: the grid's windows stop too early for four lanes to pay on ARM).
uint64_t scanDepth2_avx2(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
			 const Depth2Tree *trees, int nTrees, int32_t cascThr, WindowHit *hits,
			 uint64_t capacity);
uint64_t scanDepth2List_avx2(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			     size_t count, int step, const Depth2Tree *trees, int nTrees,
			     int32_t cascThr, WindowHit *hits, uint64_t capacity);
uint64_t scanDepth2List_neon(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			     size_t count, int step, const Depth2Tree *trees, int nTrees,
			     int32_t cascThr, WindowHit *hits, uint64_t capacity);

// AVX2 kernels whose declarations are not beside their reference: RGB8 resampling at any
// ratio in 32-bit lanes (x86/resample_rgb8_avx2.cpp), triangle smoothing in one pass per
// row (x86/smooth_avx2.cpp), the triangle sum and plane resampling.
void resampleRgb8_avx2(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp);
void smoothTri1_avx2(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		     ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp);
void triSumR_avx2(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		  int width, int height, int r, uint32_t *scratch);
void resamplePlane_avx2(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
			ptrdiff_t tmpStride);
void resamplePlanes_avx2(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			 int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			 ptrdiff_t tmpStride);

// ---- NEON kernels (lib/kernels/arm/, aarch64 and armv7 with NEON) ----------------------
// Same contracts as the references above; built only when the target has NEON.
void rgbToLuv_neon(const LuvTables &t, const uint8_t *rgb, ptrdiff_t rgbStride, int width,
		   int height, uint16_t *l, uint16_t *u, uint16_t *v, ptrdiff_t stride);
void resampleRgb8_neon(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp);
void resamplePlane_neon(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
			ptrdiff_t tmpStride);
void resamplePlanes_neon(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			 int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			 ptrdiff_t tmpStride);
void smoothTri1_neon(const uint16_t *src, ptrdiff_t srcStride, uint16_t *dst,
		     ptrdiff_t dstStride, int width, int height, uint32_t *rowTmp);
void triSumR_neon(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		  int width, int height, int r, uint32_t *scratch);
void gradMagOrient_neon(const GradientTables &t, const uint16_t *const planes[3],
			ptrdiff_t stride, int width, int height, uint16_t *mag, uint16_t *orient,
			ptrdiff_t outStride, int32_t *scratch);
void normalizeMag_neon(const GradientTables &t, uint16_t *mag, ptrdiff_t magStride,
		       const uint32_t *smoothedSum, ptrdiff_t sumStride, int width, int height);
void shrink4_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void gradHist4_neon(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch);
void shrink2_neon(const uint16_t *src, ptrdiff_t srcStride, int width, int height,
		  uint16_t *dst, ptrdiff_t dstStride, int extraShift, uint32_t *scratch);
void gradHist2_neon(const uint16_t *mag, const uint16_t *orient, ptrdiff_t stride, int width,
		    int height, int nOrients, bool interpolate, bool spatial, uint16_t *const *hist,
		    ptrdiff_t histStride, uint32_t *scratch);
// ---- end of NEON kernels ---------------------------------------------------------------

// ---- dispatch ----------------------------------------------------------------------------
// The kernels one pipeline uses, chosen once at setup. Every entry of every table
// produces output bit-identical to the reference table's.
struct KernelTable {
	const char *name;
	decltype(&rgbToLuv_ref) rgbToLuv;
	decltype(&resampleRgb8_ref) resampleRgb8;
	decltype(&resamplePlane_ref) resamplePlane;
	decltype(&resamplePlanes_ref) resamplePlanes;
	decltype(&smoothTri1_ref) smoothTri1;
	decltype(&gradMagOrient_ref) gradMagOrient;
	decltype(&triSumR_ref) triSum;
	decltype(&normalizeMag_ref) normalizeMag;
	decltype(&shrink4_ref) shrink4;
	decltype(&gradHist4_ref) gradHist4;
	decltype(&scanDepth2_ref) scanDepth2;
	decltype(&scanTrees_ref) scanTrees;
	decltype(&scanDepth2List_ref) scanDepth2List;
	decltype(&scanTreesList_ref) scanTreesList;
	// Shrink 2 (Caltech+, LDCF).
	decltype(&shrink2_ref) shrink2;
	decltype(&gradHist2_ref) gradHist2;
	// LDCF's filter (AVX2 and NEON versions; the reference in the portable table).
	decltype(&ldcfFilter_ref) ldcfFilter;
	decltype(&ldcfCell_ref) ldcfCell; // (AVX2 and NEON versions; the reference in the portable table)
};

// The plain scalar references (the specification).
const KernelTable &referenceKernels();
// The portable optimised kernels (plain C++, vectorised by the compiler).
const KernelTable &portableKernels();
// The fastest kernels this build and CPU support.
const KernelTable &bestKernels();
// Every table this build and CPU can run, references first (for tests and benchmarks).
int availableKernelTables(const KernelTable *out[], int capacity);


// ==== camera pixel formats -> interleaved RGB8 (issue 5) ================================
// Rows [y0, y0 + rows) of a camera frame converted to interleaved RGB8 rows of dst (row
// y0 at dst). The exact formulas are in ref/convert_ref.cpp and docs/pixel-formats.md.

// Q8 YUV -> RGB coefficients: with C = Y - yOffset, D = U - 128, E = V - 128,
// R = clamp((y*C + rv*E + 128) >> 8), G = clamp((y*C - gu*D - gv*E + 128) >> 8),
// B = clamp((y*C + bu*D + 128) >> 8), clamp to 0..255, >> is floor division.
struct YuvCoeffs {
	int32_t y, yOffset, rv, gu, gv, bu;
};
// BT.601 or BT.709 matrix, limited (video) or full range.
YuvCoeffs yuvCoeffs(bool bt709, bool fullRange);

// A camera frame as the conversion kernels see it (calped::ImageView, already checked).
struct RawFrame {
	const uint8_t *planes[3] = { nullptr, nullptr, nullptr }; // 4:2:0: Y, U, V
	ptrdiff_t strides[3] = { 0, 0, 0 };
	int width = 0, height = 0;
	int chromaStep = 1;     // 4:2:0: bytes between a row's chroma samples (NV12 2, I420 1)
	YuvCoeffs yuv = {};     // YUV formats
	int redX = 0, redY = 0; // Bayer: column and row of red in the top-left 2x2 block
};

using ConvertRowsFn = void (*)(const RawFrame &f, int y0, int rows, uint8_t *dst,
			       ptrdiff_t dstStride);
// B G R -> R G B.
void bgr8ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void bgr8ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
// R = G = B = the sample.
void gray8ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void gray8ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
// 4:2:0 (NV12, I420): pixel (x, y) takes chroma sample (x / 2, y / 2).
void yuv420ToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuv420ToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuv420ToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
// Packed 4:2:2 Y0 U Y1 V: both pixels of a pair take the pair's U and V.
void yuyvToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuyvToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuyvToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
// Bilinear demosaicing, borders mirrored (sample -1 is sample 1); width, height >= 2.
void bayerToRgb8_ref(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void bayerToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void bayerToRgb8_avx2(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);

// NEON versions (arm/convert_neon.cpp), sixteen pixels at a time.
void bgr8ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void gray8ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuv420ToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void yuyvToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);
void bayerToRgb8_neon(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride);

// The conversion kernels one pipeline uses (a table of their own, so the main
// KernelTable and its ISA-specific tables stay untouched).
struct ConvertKernels {
	const char *name;
	ConvertRowsFn bgr8, gray8, yuv420, yuyv, bayer;
};
const ConvertKernels &referenceConvertKernels();
const ConvertKernels &bestConvertKernels();
// Every conversion table this build and CPU can run, references first.
int availableConvertKernels(const ConvertKernels *out[], int capacity);
// ==== end of camera pixel formats ==========================================================

} // namespace kernels
} // namespace calped
