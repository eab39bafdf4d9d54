// SPDX-License-Identifier: BSD-2-Clause
// RGB8 resampling (the input "resize") with AVX2 at any ratio, in 32-bit lanes with the
// split sums of opt/resample_rgb8_split.h. Output rows are cut into groups of 32 samples
// (eight quads); the last group of a row overlaps the one before it instead of leaving a
// tail. Groups are planned a chunk at a time (on the stack), and each chunk is then run
// down every output row. Bit-identical to ref/resample_ref.cpp; when a ratio cannot be
// planned (shrinking by more than about 4.5x, or rows under 32 samples) the portable body
// runs instead.
#include <immintrin.h>

#include "opt/resample_rgb8_body.h"
#include "opt/resample_rgb8_split.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kGroup = 32;       // output samples per group: four vectors of eight
constexpr int kChunkGroups = 8;  // groups planned at a time (about 10 KB of stack)

// One vector of a group: lane 0 holds quad k of the group, lane 1 quad k + 4, so that
// two 32 -> 16 bit packs and one 16 -> 8 bit pack leave the 32 bytes in order.
// A wide window is two 16-byte loads per lane, each shuffled by its own indices.
struct VectorPlan {
	int32_t base[2];
	alignas(32) uint8_t index[kSplitMaxSteps][32];
	alignas(32) uint8_t indexHigh[kSplitMaxSteps][32]; // wide windows: bytes 16..31
	alignas(32) int16_t weight[kSplitMaxSteps][16];
};

struct GroupPlan {
	int32_t start; // first output sample
	VectorPlan v[4];
};

bool planGroup(const ResampleTap *xTaps, int start, int srcW3, int window, GroupPlan &g)
{
	g.start = start;
	for (int k = 0; k < 4; k++)
		for (int lane = 0; lane < 2; lane++) {
			QuadPlan q;
			if (!planQuad(xTaps, start + 4 * (k + 4 * lane), srcW3, window, q))
				return false;
			VectorPlan &v = g.v[k];
			v.base[lane] = q.base;
			for (int step = 0; step < kSplitMaxSteps; step++) {
				for (int b = 0; b < 16; b++) {
					const uint8_t i = q.index[step][b];
					const bool high = i != kZeroByte && i >= 16;
					v.index[step][16 * lane + b] = high ? kZeroByte : i;
					v.indexHigh[step][16 * lane + b] = high ? uint8_t(i - 16) : kZeroByte;
				}
				for (int w = 0; w < 8; w++)
					v.weight[step][8 * lane + w] = q.weight[step][w];
			}
		}
	return true;
}

// Group starts: every 32 samples, the last one moved back to end at the row's end.
inline int groupCount(int dstW3)
{
	return (dstW3 + kGroup - 1) / kGroup;
}
inline int groupStart(int g, int dstW3)
{
	return g * kGroup + kGroup <= dstW3 ? g * kGroup : dstW3 - kGroup;
}

inline __m256i loadLanes(const uint8_t *lane0, const uint8_t *lane1)
{
	return _mm256_inserti128_si256(
		_mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i *>(lane0))),
		_mm_loadu_si128(reinterpret_cast<const __m128i *>(lane1)), 1);
}

// Row sums H = sum_x wx * p of one vector (eight samples) of one source row.
template <int Steps, bool Wide>
inline __m256i rowSums(const uint8_t *row, const VectorPlan &v)
{
	const uint8_t *p0 = row + v.base[0], *p1 = row + v.base[1];
	const __m256i bytes = loadLanes(p0, p1);
	const __m256i high = Wide ? loadLanes(p0 + 16, p1 + 16) : bytes;
	const __m256i *index = reinterpret_cast<const __m256i *>(v.index);
	const __m256i *indexHigh = reinterpret_cast<const __m256i *>(v.indexHigh);
	const __m256i *weight = reinterpret_cast<const __m256i *>(v.weight);
	__m256i h = _mm256_setzero_si256();
	for (int step = 0; step < Steps; step++) {
		__m256i pairs = _mm256_shuffle_epi8(bytes, _mm256_load_si256(index + step));
		if (Wide)
			pairs = _mm256_or_si256(pairs, _mm256_shuffle_epi8(high, _mm256_load_si256(indexHigh + step)));
		const __m256i sums = _mm256_madd_epi16(pairs, _mm256_load_si256(weight + step));
		h = step == 0 ? sums : _mm256_add_epi32(h, sums);
	}
	return h;
}

// Column sums of two source rows' split row sums: (hi0, hi1) and (lo0, lo1) as 16-bit
// pairs against the pair of weights (w0, w1).
inline void addRowPair(__m256i h0, __m256i h1, __m256i wPair, __m256i &a, __m256i &b)
{
	const __m256i hiPair = _mm256_blend_epi16(_mm256_srli_epi32(h0, 14), _mm256_slli_epi32(h1, 2), 0xAA);
	const __m256i loPair = _mm256_and_si256(_mm256_blend_epi16(h0, _mm256_slli_epi32(h1, 16), 0xAA),
						_mm256_set1_epi32(0x3FFF3FFF));
	a = _mm256_add_epi32(a, _mm256_madd_epi16(hiPair, wPair));
	b = _mm256_add_epi32(b, _mm256_madd_epi16(loPair, wPair));
}

// (A + ((B + 2^27 - 1) >> 14)) >> 14: exact halves round down.
inline __m256i roundSplit(__m256i a, __m256i b)
{
	b = _mm256_srli_epi32(_mm256_add_epi32(b, _mm256_set1_epi32((1 << 27) - 1)), 14);
	return _mm256_srli_epi32(_mm256_add_epi32(a, b), 14);
}

// Weights j and j + 1 of a tap as one 32-bit lane (0 past the last).
inline int32_t weightPair(const ResampleTap &t, int j)
{
	return (t.weight[j] & 0xFFFF) | (j + 1 < t.count ? t.weight[j + 1] << 16 : 0);
}

// Output rows of at most two source rows (every enlarging row): r1 is r0 again, at weight
// 0, when there is one.
template <int Steps, bool Wide>
inline __m256i vectorOutTwo(const uint8_t *r0, const uint8_t *r1, __m256i wPair, const VectorPlan &v)
{
	__m256i a = _mm256_setzero_si256(), b = a;
	addRowPair(rowSums<Steps, Wide>(r0, v), rowSums<Steps, Wide>(r1, v), wPair, a, b);
	return roundSplit(a, b);
}

template <int Steps, bool Wide>
inline __m256i vectorOutMany(const uint8_t *r0, ptrdiff_t srcStride, const ResampleTap &ty,
			     const VectorPlan &v)
{
	__m256i a = _mm256_setzero_si256(), b = a;
	for (int j = 0; j < ty.count; j += 2) {
		const __m256i h0 = rowSums<Steps, Wide>(r0 + j * srcStride, v);
		const __m256i h1 = j + 1 < ty.count ? rowSums<Steps, Wide>(r0 + (j + 1) * srcStride, v) : h0;
		addRowPair(h0, h1, _mm256_set1_epi32(weightPair(ty, j)), a, b);
	}
	return roundSplit(a, b);
}

inline void storeGroup(uint8_t *out, __m256i o0, __m256i o1, __m256i o2, __m256i o3)
{
	const __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(o0, o1), _mm256_packs_epi32(o2, o3));
	_mm256_storeu_si256(reinterpret_cast<__m256i *>(out), bytes);
}

template <int Steps, bool Wide>
void runChunk(const uint8_t *src, ptrdiff_t srcStride, uint8_t *dst, ptrdiff_t dstStride,
	      int dstHeight, const ResampleTap *yTaps, const GroupPlan *groups, int nGroups)
{
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &ty = yTaps[y];
		const uint8_t *r0 = src + ty.first * srcStride;
		uint8_t *out = dst + y * dstStride;
		if (ty.count <= 2) {
			const uint8_t *r1 = ty.count == 2 ? r0 + srcStride : r0;
			const __m256i w = _mm256_set1_epi32(weightPair(ty, 0));
			for (int g = 0; g < nGroups; g++) {
				const GroupPlan &p = groups[g];
				storeGroup(out + p.start, vectorOutTwo<Steps, Wide>(r0, r1, w, p.v[0]),
					   vectorOutTwo<Steps, Wide>(r0, r1, w, p.v[1]), vectorOutTwo<Steps, Wide>(r0, r1, w, p.v[2]),
					   vectorOutTwo<Steps, Wide>(r0, r1, w, p.v[3]));
			}
			continue;
		}
		for (int g = 0; g < nGroups; g++) {
			const GroupPlan &p = groups[g];
			storeGroup(out + p.start, vectorOutMany<Steps, Wide>(r0, srcStride, ty, p.v[0]),
				   vectorOutMany<Steps, Wide>(r0, srcStride, ty, p.v[1]),
				   vectorOutMany<Steps, Wide>(r0, srcStride, ty, p.v[2]),
				   vectorOutMany<Steps, Wide>(r0, srcStride, ty, p.v[3]));
		}
	}
}

using RunChunkFn = void (*)(const uint8_t *src, ptrdiff_t srcStride, uint8_t *dst, ptrdiff_t dstStride,
			    int dstHeight, const ResampleTap *yTaps, const GroupPlan *groups, int nGroups);

RunChunkFn chunkRunner(int steps, bool wide)
{
	static const RunChunkFn narrow[] = { runChunk<1, false>, runChunk<2, false> };
	static const RunChunkFn wideWindow[] = { runChunk<1, true>, runChunk<2, true>, runChunk<3, true> };
	return wide ? wideWindow[steps - 1] : narrow[steps - 1];
}

// The window every group of a row plans in: 16 bytes, else 32, else 0 (none).
int planWindow(const ResampleTap *xTaps, int dstWidth, int srcW3, GroupPlan &scratch)
{
	const int dstW3 = 3 * dstWidth;
	for (int window : { kSplitNarrow, kSplitWide }) {
		bool planned = splitSumsFit(xTaps, dstWidth, splitMaxXTaps(window));
		for (int g = 0; g < groupCount(dstW3) && planned; g++)
			planned = planGroup(xTaps, groupStart(g, dstW3), srcW3, window, scratch);
		if (planned)
			return window;
	}
	return 0;
}

} // namespace

void resampleRgb8_avx2(const uint8_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
		       uint8_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		       const ResampleTap *xTaps, const ResampleTap *yTaps, int32_t *rowTmp)
{
	const int srcW3 = 3 * srcWidth, dstW3 = 3 * dstWidth;
	GroupPlan chunk[kChunkGroups];
	// Every group must plan before any output is written.
	const int window = dstW3 >= kGroup && splitSumsFit(yTaps, dstHeight, kMaxTaps)
				   ? planWindow(xTaps, dstWidth, srcW3, chunk[0])
				   : 0;
	if (window == 0) {
		resampleRgb8Body(src, srcStride, srcWidth, srcHeight, dst, dstStride, dstWidth,
				 dstHeight, xTaps, yTaps, rowTmp);
		return;
	}
	const RunChunkFn run = chunkRunner(splitSteps(xTaps, dstWidth), window == kSplitWide);
	const int nGroups = groupCount(dstW3);
	for (int g0 = 0; g0 < nGroups; g0 += kChunkGroups) {
		const int n = nGroups - g0 < kChunkGroups ? nGroups - g0 : kChunkGroups;
		for (int g = 0; g < n; g++)
			planGroup(xTaps, groupStart(g0 + g, dstW3), srcW3, window, chunk[g]);
		run(src, srcStride, dst, dstStride, dstHeight, yTaps, chunk, n);
	}
}

} // namespace kernels
} // namespace calped
