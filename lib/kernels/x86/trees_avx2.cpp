// SPDX-License-Identifier: BSD-2-Clause
// Depth-2 trees over eight windows at a time with AVX2 (the scheme is in trees_batch.h):
// the two feature reads of a tree are gathers, the tree's own fields broadcasts.
// Bit-identical to ref/trees_ref.cpp's scanDepth2_ref and scanDepth2List_ref.
#include <immintrin.h>

#include <cstdint>

#include "kernels.h"
#include "trees_batch.h"

namespace calped {
namespace kernels {

namespace {

// With this many running lanes or fewer a batch is finished by the scalar loop: a step of the
// eight-lane walk costs about as much as three scalar trees (callgrind: 1 and 2 within 1%
// of each other, 3 and 4 worse; docs/benchmarks.md).
constexpr int kScalarBelow = 2;

// Set bits of an eight-bit mask (AVX2 does not imply the popcnt instruction).
struct BitCounts {
	uint8_t n[256];
	constexpr BitCounts() : n()
	{
		for (int i = 0; i < 256; i++)
			n[i] = uint8_t((i & 1) + (i >> 1 & 1) + (i >> 2 & 1) + (i >> 3 & 1) + (i >> 4 & 1) +
				       (i >> 5 & 1) + (i >> 6 & 1) + (i >> 7 & 1));
	}
};
constexpr BitCounts kBitCounts;

// The samples at element offsets idx of a 4-byte aligned uint16 array. Each lane reads
// the aligned 32-bit word holding its sample, so no read reaches past the buffer's last
// word (a 32-bit read at the sample itself could, for the buffer's last sample).
inline __m256i features8(const int *words, __m256i idx)
{
	const __m256i w = _mm256_i32gather_epi32(words, _mm256_srli_epi32(idx, 1), 4);
	const __m256i shift = _mm256_slli_epi32(_mm256_and_si256(idx, _mm256_set1_epi32(1)), 4);
	return _mm256_and_si256(_mm256_srlv_epi32(w, shift), _mm256_set1_epi32(0xFFFF));
}

// A tree's fields as eight lanes (off[0..2], thr[0..2], leaf[0..1]) and its four leaves,
// for picking per lane with permutes instead of blends of broadcasts.
static_assert(sizeof(Depth2Tree) == 40, "Depth2Tree: off[3], thr[3], leaf[4] packed");

struct Avx2Walk {
	void operator()(const uint16_t *chns, const int32_t *base, int n, const Depth2Tree *trees,
			int nTrees, int32_t cascThr, int scalarBelow, BatchState &s) const
	{
		const uintptr_t a = reinterpret_cast<uintptr_t>(chns);
		const int *words = reinterpret_cast<const int *>(a & ~uintptr_t(3));
		const __m256i b = _mm256_add_epi32(
			_mm256_loadu_si256(reinterpret_cast<const __m256i *>(base)),
			_mm256_set1_epi32(int32_t((a & 2) >> 1)));
		const __m256i thr = _mm256_set1_epi32(cascThr);
		const __m256i two = _mm256_set1_epi32(2), three = _mm256_set1_epi32(3),
			      five = _mm256_set1_epi32(5);
		__m256i running = _mm256_cmpgt_epi32(_mm256_set1_epi32(n),
						     _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
		__m256i h = _mm256_setzero_si256();
		int live = n, t = 0;
		for (; t < nTrees && live > scalarBelow; t++) {
			const Depth2Tree &tr = trees[t];
			const __m256i fields = _mm256_loadu_si256(reinterpret_cast<const __m256i *>(&tr));
			const __m256i leaves = _mm256_castsi128_si256(
				_mm_loadu_si128(reinterpret_cast<const __m128i *>(tr.leaf)));
			// Masks of "feature < threshold" (all ones): f >= thr is their complement, and
			// f < thr needs no care for thresholds outside the features' range.
			const __m256i f0 =
				features8(words, _mm256_add_epi32(b, _mm256_set1_epi32(int32_t(tr.off[0]))));
			const __m256i left = _mm256_cmpgt_epi32(_mm256_set1_epi32(tr.thr[0]), f0);
			// Second node: node 1 (fields off[1], thr[1]: 1 and 4) when left (-1), else node
			// 2 (fields 2 and 5).
			const __m256i off = _mm256_permutevar8x32_epi32(fields, _mm256_add_epi32(two, left));
			const __m256i thr1 = _mm256_permutevar8x32_epi32(fields, _mm256_add_epi32(five, left));
			const __m256i f1 = features8(words, _mm256_add_epi32(b, off));
			const __m256i left1 = _mm256_cmpgt_epi32(thr1, f1);
			// Leaf 3 + 2 left + left1: 0 left-left, 1 left-right, 2 right-left, 3 right-right.
			const __m256i leafIndex =
				_mm256_add_epi32(three, _mm256_add_epi32(_mm256_add_epi32(left, left), left1));
			const __m256i leaf = _mm256_permutevar8x32_epi32(leaves, leafIndex);
			h = _mm256_add_epi32(h, _mm256_and_si256(leaf, running));
			running = _mm256_and_si256(running, _mm256_cmpgt_epi32(h, thr));
			live = kBitCounts.n[_mm256_movemask_ps(_mm256_castsi256_ps(running))];
		}
		alignas(32) int32_t run[8];
		_mm256_storeu_si256(reinterpret_cast<__m256i *>(s.h), h);
		_mm256_store_si256(reinterpret_cast<__m256i *>(run), running);
		for (int l = 0; l < 8; l++)
			s.running[l] = run[l] != 0;
		s.tree = t;
	}
};

} // namespace

uint64_t scanDepth2_avx2(const uint16_t *chns, ptrdiff_t rowStride, int rows, int cols, int step,
			 const Depth2Tree *trees, int nTrees, int32_t cascThr, WindowHit *hits,
			 uint64_t capacity)
{
	if (rows <= 0 || cols <= 0)
		return 0;
	const GridWindows win = { rows, cols, step, rowStride, 0, 0 };
	return scanDepth2Batched<8>(chns, win, trees, nTrees, cascThr, kScalarBelow, hits, capacity,
				    Avx2Walk());
}

uint64_t scanDepth2List_avx2(const uint16_t *chns, ptrdiff_t rowStride, const uint32_t *windows,
			     size_t count, int step, const Depth2Tree *trees, int nTrees,
			     int32_t cascThr, WindowHit *hits, uint64_t capacity)
{
	const ListWindows win = { windows, count, step, rowStride, 0 };
	return scanDepth2Batched<8>(chns, win, trees, nTrees, cascThr, kScalarBelow, hits, capacity,
				    Avx2Walk());
}

} // namespace kernels
} // namespace calped
