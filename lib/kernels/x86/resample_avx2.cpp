// SPDX-License-Identifier: BSD-2-Clause
// Plane resampling with AVX2. The row pass, which the portable code does one sample at
// a time, works here on blocks of eight outputs, four per 128-bit lane, whose taps (at
// most four) fall within eight consecutive samples of that lane (any ratio below about
// 1.7): byte shuffles put each output's samples side by side and 16-bit multiply-adds
// weigh them. Samples are offset by -32768 to fit the signed multiply, and the offset
// times the weights' sum is added back (the sums wrap exactly modulo 2^32). Blocks that
// shrink more (up to 8 taps an output) multiply each output's 8 samples by its weights
// and add across lanes. The column pass uses the same multiply-add on two rows at a
// time. Bit-identical to ref/resample_ref.cpp.
#include <immintrin.h>

#include "opt/resample_body.h"

namespace calped {
namespace kernels {

namespace {

constexpr int kChunk = 64; // blocks planned at a time (bounded stack use)

enum class BlockKind : int32_t { Scalar, Pairs, Wide };

// Samples enter the multiply-add as int16, offset by -32768; weights must fit int16 and
// their sum keep every true total below 2^32.
constexpr int32_t kSampleOffset = 32768;
constexpr int32_t kMaxPairWeight = 32767;
constexpr int32_t kMaxWeightSum = 65535;

inline int32_t weightSum(const ResampleTap &t)
{
	int32_t sum = 0;
	for (int j = 0; j < t.count; j++)
		sum += t.weight[j];
	return sum;
}

// Up to four taps per output, each lane's four outputs within eight samples from that
// lane's base: shuffle[k] picks taps 2k and 2k+1 as adjacent int16 pairs.
struct PairPlan {
	int32_t base[2];        // first source sample of each lane
	int32_t pairs;          // 1 or 2 tap pairs
	uint8_t shuffle[2][32]; // per tap pair, bytes of the lane's 16-byte load
	int16_t weight[2][16];  // per tap pair, (w[2k], w[2k+1]) per output
	uint32_t bias[8];       // kSampleOffset * sum of weights + rounding half
};

// Shrinking by about 2 to 8: each output's up to 8 taps, weights 0 past its count.
struct WidePlan {
	int32_t first[8];
	int32_t weight[8][8];
};

struct BlockPlan {
	BlockKind kind;
	int32_t x0; // first output of the block
	union {
		PairPlan pairs;
		WidePlan wide;
	};
};

bool planPairs(const ResampleTap *taps, int x0, int srcWidth, PairPlan &p)
{
	if (srcWidth < 8)
		return false;
	p.pairs = 1;
	for (int lane = 0; lane < 2; lane++) {
		// The eight samples start at the lane's first tap, or earlier at the right edge
		// so that they stay inside the row.
		const int base = std::min(taps[x0 + 4 * lane].first, srcWidth - 8);
		p.base[lane] = base;
		for (int k = 0; k < 4; k++) {
			const int o = 4 * lane + k;
			const ResampleTap &t = taps[x0 + o];
			if (t.count > 4 || t.first < base || t.first + t.count - base > 8)
				return false;
			const int32_t sum = weightSum(t);
			if (sum > kMaxWeightSum)
				return false;
			p.bias[o] = uint32_t(kSampleOffset) * uint32_t(sum) + (1u << (kQ - 1));
			if (t.count > 2)
				p.pairs = 2;
			for (int j = 0; j < 4; j++) {
				if (j < t.count && t.weight[j] > kMaxPairWeight)
					return false;
				// A missing tap reads the output's first sample with weight 0.
				const int sample = (j < t.count ? t.first + j : t.first) - base;
				const int pair = j / 2, at = 16 * lane + 4 * k + 2 * (j % 2);
				p.shuffle[pair][at] = uint8_t(2 * sample);
				p.shuffle[pair][at + 1] = uint8_t(2 * sample + 1);
				p.weight[pair][2 * o + j % 2] = int16_t(j < t.count ? t.weight[j] : 0);
			}
		}
	}
	return true;
}

bool planWide(const ResampleTap *taps, int x0, int srcWidth, WidePlan &p)
{
	for (int i = 0; i < 8; i++) {
		const ResampleTap &t = taps[x0 + i];
		if (t.count > 8 || t.first + 8 > srcWidth)
			return false;
		p.first[i] = t.first;
		for (int j = 0; j < 8; j++)
			p.weight[i][j] = j < t.count ? t.weight[j] : 0;
	}
	return true;
}

void planBlock(const ResampleTap *taps, int x0, int srcWidth, BlockPlan &p)
{
	p.x0 = x0;
	if (planPairs(taps, x0, srcWidth, p.pairs))
		p.kind = BlockKind::Pairs;
	else if (planWide(taps, x0, srcWidth, p.wide))
		p.kind = BlockKind::Wide;
	else
		p.kind = BlockKind::Scalar;
}

inline __m256i loadConst(const void *p)
{
	return _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p));
}

// Eight samples from each lane's base, as int16 offset by -32768.
inline __m256i loadLanes(const uint16_t *in, const int32_t base[2])
{
	const __m256i both = _mm256_inserti128_si256(
		_mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i *>(in + base[0]))),
		_mm_loadu_si128(reinterpret_cast<const __m128i *>(in + base[1])), 1);
	return _mm256_xor_si256(both, _mm256_set1_epi16(-0x8000));
}

// A wide block: each output's 8 samples times its 8 weights, summed across
// lanes (products below 2^31, sums below 2^32, so the wrapping adds are exact).
inline __m256i wideSums(const WidePlan &p, const uint16_t *in, __m256i acc)
{
	__m256i prod[8];
	for (int i = 0; i < 8; i++) {
		const __m256i s = _mm256_cvtepu16_epi32(
			_mm_loadu_si128(reinterpret_cast<const __m128i *>(in + p.first[i])));
		const __m256i w = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p.weight[i]));
		prod[i] = _mm256_mullo_epi32(s, w);
	}
	// Pairwise adds leave, in each 128-bit half, partial sums of outputs 0-3 (g0) and 4-7
	// (g1); the two halves then add up.
	const __m256i g0 = _mm256_hadd_epi32(_mm256_hadd_epi32(prod[0], prod[1]),
					     _mm256_hadd_epi32(prod[2], prod[3]));
	const __m256i g1 = _mm256_hadd_epi32(_mm256_hadd_epi32(prod[4], prod[5]),
					     _mm256_hadd_epi32(prod[6], prod[7]));
	return _mm256_add_epi32(acc, _mm256_add_epi32(_mm256_permute2x128_si256(g0, g1, 0x20),
						      _mm256_permute2x128_si256(g0, g1, 0x31)));
}

inline uint32_t tapSum(const ResampleTap &t, const uint16_t *in)
{
	uint32_t acc = 0;
	for (int j = 0; j < t.count; j++)
		acc += uint32_t(t.weight[j]) * in[t.first + j];
	return acc;
}

bool isHalving(const ResampleTap *taps, int dstWidth)
{
	for (int x = 0; x < dstWidth; x++) {
		const ResampleTap &t = taps[x];
		if (t.count != 2 || t.first != 2 * x || t.weight[0] != kOne / 2 || t.weight[1] != kOne / 2)
			return false;
	}
	return true;
}

// Exactly half the width: (a + b + 1) >> 1 is the unsigned average instruction.
void halveRows(const uint16_t *src, ptrdiff_t srcStride, int srcHeight, int dstWidth,
	       uint16_t *tmp, ptrdiff_t tmpStride)
{
	const __m256i lowHalf = _mm256_set1_epi32(0xFFFF);
	for (int y = 0; y < srcHeight; y++) {
		const uint16_t *in = src + y * srcStride;
		uint16_t *out = tmp + y * tmpStride;
		int x = 0;
		for (; x + 16 <= dstWidth; x += 16) {
			const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + 2 * x));
			const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(in + 2 * x + 16));
			// Even samples in the low halves of 32-bit lanes, odd ones in the high halves.
			const __m256i even = _mm256_packus_epi32(_mm256_and_si256(a, lowHalf), _mm256_and_si256(b, lowHalf));
			const __m256i odd = _mm256_packus_epi32(_mm256_srli_epi32(a, 16), _mm256_srli_epi32(b, 16));
			const __m256i avg = _mm256_permute4x64_epi64(_mm256_avg_epu16(even, odd), 0xD8);
			_mm256_storeu_si256(reinterpret_cast<__m256i *>(out + x), avg);
		}
		for (; x < dstWidth; x++)
			out[x] = static_cast<uint16_t>((uint32_t(in[2 * x]) + in[2 * x + 1] + 1) >> 1);
	}
}

// The column pass: each output row from two source rows at a time, sixteen samples
// interleaved into (row a, row b) pairs for the multiply-add. Rows whose taps do not
// fit the 16-bit form take the portable body.
bool columnFitsPairs(const ResampleTap &t)
{
	if (t.count < 2 || t.count > 4 || weightSum(t) > kMaxWeightSum)
		return false;
	for (int j = 0; j < t.count; j++)
		if (t.weight[j] > kMaxPairWeight)
			return false;
	return true;
}

inline __m256i loadOffset(const uint16_t *p)
{
	return _mm256_xor_si256(_mm256_loadu_si256(reinterpret_cast<const __m256i *>(p)),
				_mm256_set1_epi16(-0x8000));
}

// Sixteen outputs of one row: rows[j] + x for the taps' rows, w[k] their weight pairs.
inline void columnBlock(const uint16_t *const rows[4], int count, const __m256i w[2], __m256i bias,
			int x, uint16_t *out)
{
	const __m256i a = loadOffset(rows[0] + x), b = loadOffset(rows[1] + x);
	__m256i lo = _mm256_add_epi32(bias, _mm256_madd_epi16(_mm256_unpacklo_epi16(a, b), w[0]));
	__m256i hi = _mm256_add_epi32(bias, _mm256_madd_epi16(_mm256_unpackhi_epi16(a, b), w[0]));
	if (count > 2) {
		// A missing fourth tap reads the third row again with weight 0.
		const __m256i c = loadOffset(rows[2] + x), d = loadOffset(rows[count > 3 ? 3 : 2] + x);
		lo = _mm256_add_epi32(lo, _mm256_madd_epi16(_mm256_unpacklo_epi16(c, d), w[1]));
		hi = _mm256_add_epi32(hi, _mm256_madd_epi16(_mm256_unpackhi_epi16(c, d), w[1]));
	}
	// The unpacks split each lane into samples 0-3 and 4-7; packing them in lane order
	// restores it. Shifted sums are below 2^18: packing saturates them to 65535.
	const __m256i v = _mm256_packus_epi32(_mm256_srli_epi32(lo, kQ), _mm256_srli_epi32(hi, kQ));
	_mm256_storeu_si256(reinterpret_cast<__m256i *>(out + x), v);
}

void columnPass(uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
		const ResampleTap *yTaps, const uint16_t *tmp, ptrdiff_t tmpStride)
{
	for (int y = 0; y < dstHeight; y++) {
		const ResampleTap &t = yTaps[y];
		if (dstWidth < 16 || !columnFitsPairs(t)) {
			resampleColumnsBody(dst + y * dstStride, dstStride, dstWidth, 1, &t, tmp, tmpStride);
			continue;
		}
		const uint16_t *rows[4];
		for (int j = 0; j < 4; j++)
			rows[j] = tmp + (t.first + std::min(j, t.count - 1)) * tmpStride;
		auto pair = [&](int j) {
			const int16_t w0 = int16_t(j < t.count ? t.weight[j] : 0);
			const int16_t w1 = int16_t(j + 1 < t.count ? t.weight[j + 1] : 0);
			return _mm256_set1_epi32(int32_t(uint16_t(w0)) | int32_t(uint32_t(uint16_t(w1)) << 16));
		};
		const __m256i w[2] = { pair(0), pair(2) };
		const __m256i bias =
			_mm256_set1_epi32(int32_t(uint32_t(kSampleOffset) * uint32_t(weightSum(t)) + (1u << (kQ - 1))));
		uint16_t *out = dst + y * dstStride;
		int x = 0;
		for (; x + 16 <= dstWidth; x += 16)
			columnBlock(rows, t.count, w, bias, x, out);
		// The last few: one more block ending at the row's end (same values where the
		// blocks overlap).
		if (x < dstWidth)
			columnBlock(rows, t.count, w, bias, dstWidth - 16, out);
	}
}

// Rounded unsigned sums below 2^32 of eight outputs: shifted logically, saturated to
// 16 bits and stored.
inline void storeSums(__m256i acc, uint16_t *out)
{
	const __m256i v = _mm256_min_epu32(_mm256_srli_epi32(acc, kQ), _mm256_set1_epi32(65535));
	const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(v, v), 0xD8);
	_mm_storeu_si128(reinterpret_cast<__m128i *>(out), _mm256_castsi256_si128(packed));
}

// A pair block down every source row, its plan held in registers.
template <int Pairs>
void pairBlockRows(const PairPlan &p, const uint16_t *src, ptrdiff_t srcStride, int srcHeight,
		   uint16_t *out, ptrdiff_t tmpStride)
{
	const __m256i bias = loadConst(p.bias);
	const __m256i shuffle0 = loadConst(p.shuffle[0]), weight0 = loadConst(p.weight[0]);
	const __m256i shuffle1 = loadConst(p.shuffle[1]), weight1 = loadConst(p.weight[1]);
	for (int y = 0; y < srcHeight; y++) {
		const __m256i s = loadLanes(src + y * srcStride, p.base);
		__m256i acc = _mm256_add_epi32(bias, _mm256_madd_epi16(_mm256_shuffle_epi8(s, shuffle0), weight0));
		if (Pairs > 1)
			acc = _mm256_add_epi32(acc, _mm256_madd_epi16(_mm256_shuffle_epi8(s, shuffle1), weight1));
		storeSums(acc, out + y * tmpStride);
	}
}

// The row pass of one chunk of blocks (outputs [x0, end)) over every source row: in bands
// of rows that stay in the caches nearest the core, block by block down the band's rows, so
// that each block's plan is read once a band.
constexpr int kBandRows = 32;

void rowPassChunk(const uint16_t *src, ptrdiff_t srcStride, int srcHeight, const BlockPlan *plans,
		  int blocks, int tail, int end, const ResampleTap *xTaps, uint16_t *tmp,
		  ptrdiff_t tmpStride)
{
	const __m256i half = _mm256_set1_epi32(1 << (kQ - 1));
	for (int y0 = 0; y0 < srcHeight; y0 += kBandRows) {
		const int rows = std::min(kBandRows, srcHeight - y0);
		const uint16_t *in = src + y0 * srcStride;
		uint16_t *out = tmp + y0 * tmpStride;
		for (int b = 0; b < blocks; b++) {
			const BlockPlan &p = plans[b];
			const int x0 = p.x0;
			if (p.kind == BlockKind::Pairs) {
				if (p.pairs.pairs > 1)
					pairBlockRows<2>(p.pairs, in, srcStride, rows, out + x0, tmpStride);
				else
					pairBlockRows<1>(p.pairs, in, srcStride, rows, out + x0, tmpStride);
			} else if (p.kind == BlockKind::Wide) {
				for (int y = 0; y < rows; y++)
					storeSums(wideSums(p.wide, in + y * srcStride, half), out + y * tmpStride + x0);
			} else {
				for (int y = 0; y < rows; y++)
					for (int x = x0; x < x0 + 8; x++)
						out[y * tmpStride + x] = roundQ14(tapSum(xTaps[x], in + y * srcStride));
			}
		}
		for (int y = 0; y < rows; y++)
			for (int x = tail; x < end; x++)
				out[y * tmpStride + x] = roundQ14(tapSum(xTaps[x], in + y * srcStride));
	}
}

} // namespace

// Chunk by chunk of outputs: the blocks are planned once, then each plane's rows and
// columns in that chunk are resampled (tmp holds one plane's chunk at a time).
void resamplePlanes_avx2(const PlaneJob *jobs, int count, int srcWidth, int srcHeight,
			 int dstWidth, int dstHeight, const ResampleTap *xTaps, uint16_t *tmp,
			 ptrdiff_t tmpStride)
{
	if (isHalving(xTaps, dstWidth)) {
		for (int i = 0; i < count; i++) {
			const PlaneJob &j = jobs[i];
			halveRows(j.src, j.srcStride, srcHeight, dstWidth, tmp, tmpStride);
			columnPass(j.dst, j.dstStride, dstWidth, dstHeight, j.yTaps, tmp, tmpStride);
		}
		return;
	}
	BlockPlan plans[kChunk + 1];
	for (int chunk = 0; chunk < dstWidth; chunk += 8 * kChunk) {
		int blocks = std::min(kChunk, (dstWidth - chunk) / 8);
		const int end = std::min(dstWidth, chunk + 8 * kChunk);
		for (int b = 0; b < blocks; b++)
			planBlock(xTaps, chunk + 8 * b, srcWidth, plans[b]);
		// The last few outputs: one more block ending at the row's end, overlapping
		// the one before (it writes the same values there), or one sample at a time.
		int tail = chunk + 8 * blocks;
		if (tail < end && dstWidth >= 8) {
			planBlock(xTaps, dstWidth - 8, srcWidth, plans[blocks++]);
			tail = end;
		}
		// The columns this chunk's blocks write (the overlapping block starts earlier).
		const int from = blocks > 0 ? std::min(chunk, plans[blocks - 1].x0) : chunk;
		for (int i = 0; i < count; i++) {
			const PlaneJob &j = jobs[i];
			rowPassChunk(j.src, j.srcStride, srcHeight, plans, blocks, tail, end, xTaps, tmp,
				     tmpStride);
			columnPass(j.dst + from, j.dstStride, end - from, dstHeight, j.yTaps, tmp + from,
				   tmpStride);
		}
	}
}

void resamplePlane_avx2(const uint16_t *src, ptrdiff_t srcStride, int srcWidth, int srcHeight,
			uint16_t *dst, ptrdiff_t dstStride, int dstWidth, int dstHeight,
			const ResampleTap *xTaps, const ResampleTap *yTaps, uint16_t *tmp,
			ptrdiff_t tmpStride)
{
	const PlaneJob job = { src, srcStride, dst, dstStride, yTaps };
	resamplePlanes_avx2(&job, 1, srcWidth, srcHeight, dstWidth, dstHeight, xTaps, tmp, tmpStride);
}

} // namespace kernels
} // namespace calped
