// SPDX-License-Identifier: BSD-2-Clause
// Triangle sum of radius r with AVX2. The portable build's horizontal pass keeps two
// running sums along each row, one pixel after the other; here each row is summed as two
// boxes of r + 1 taps, eight pixels at a time: the box of the symmetrically padded row
// into one scratch row, then the box of that box, which is the triangle 1..r+1..1. The
// vertical pass keeps the portable build's two running sums (smooth_body.h), fused into one
// loop over each row.
// Integer sums in another order, so bit-identical to ref/smooth_ref.cpp.
#include <immintrin.h>

#include "opt/smooth_body.h"

namespace calped {
namespace kernels {

namespace {

inline __m256i load8(const uint32_t *p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i *>(p)); }
inline void store8(uint32_t *p, __m256i v) { _mm256_storeu_si256(reinterpret_cast<__m256i *>(p), v); }

// out[m] = in[m] + ... + in[m + r] for m in [0, n). R > 0: r = R, unrolled; R = 0: any r.
template <int R>
void boxRow(const uint32_t *in, int n, int r, uint32_t *out)
{
	if constexpr (R > 0)
		r = R;
	int m = 0;
	for (; m + 8 <= n; m += 8) {
		__m256i acc = load8(in + m);
#pragma GCC unroll 16
		for (int j = 1; j <= r; j++)
			acc = _mm256_add_epi32(acc, load8(in + m + j));
		store8(out + m, acc);
	}
	for (; m < n; m++) {
		uint32_t acc = 0;
		for (int j = 0; j <= r; j++)
			acc += in[m + j];
		out[m] = acc;
	}
}

// The vertical pass of triSumColumnsBody with its two loops over a row fused, eight
// columns at a time (as arm/trisum_neon.cpp does with four).
void verticalPass(const TriSumScratch &s, uint32_t *dst, ptrdiff_t dstStride, int width,
		  int height, int r)
{
	auto q = [&](int m) { return triSumPaddedRow(s, m, width, height, r); };
	uint32_t *acc1 = s.acc1, *acc2 = s.acc2;
	triSumColumnsStart(s, width, height, r);
	for (int m = 0; m < height + r; m++) {
		const uint32_t *in = q(m + r);
		const uint32_t *leaving = q(m);
		uint32_t *box = s.ring + size_t(m % (r + 1)) * width;
		const bool emit = m >= r;
		uint32_t *out = emit ? dst + (m - r) * dstStride : nullptr;
		// Box row m - r, the oldest in acc2's window once it is full (with r = 0 it is
		// row m itself, hence the store of row m first).
		const uint32_t *oldest = emit ? s.ring + size_t((m - r) % (r + 1)) * width : nullptr;
		int x = 0;
		for (; x + 8 <= width; x += 8) {
			const __m256i a1 = _mm256_add_epi32(load8(acc1 + x), load8(in + x));
			__m256i a2 = _mm256_add_epi32(load8(acc2 + x), a1);
			store8(box + x, a1);
			store8(acc1 + x, _mm256_sub_epi32(a1, load8(leaving + x)));
			if (emit) {
				store8(out + x, a2);
				a2 = _mm256_sub_epi32(a2, load8(oldest + x));
			}
			store8(acc2 + x, a2);
		}
		for (; x < width; x++) {
			const uint32_t a1 = acc1[x] + in[x];
			uint32_t a2 = acc2[x] + a1;
			box[x] = a1;
			acc1[x] = a1 - leaving[x];
			if (emit) {
				out[x] = a2;
				a2 -= oldest[x];
			}
			acc2[x] = a2;
		}
	}
}


template <int R>
void horizontalPass(const uint16_t *src, ptrdiff_t srcStride, int width, int height, int r,
		    const TriSumScratch &s)
{
	for (int y = 0; y < height; y++) {
		padRow(src + y * srcStride, width, r, s.padded);  // width + 2r samples
		boxRow<R>(s.padded, width + r, r, s.boxRow);      // width + r boxes
		boxRow<R>(s.boxRow, width, r, s.horiz + size_t(y) * width);
	}
}

} // namespace

void triSumR_avx2(const uint16_t *src, ptrdiff_t srcStride, uint32_t *dst, ptrdiff_t dstStride,
		  int width, int height, int r, uint32_t *scratch)
{
	const TriSumScratch s(scratch, width, height, r);
	switch (r) { // the toolbox's normalisation radius is 5
	case 1: horizontalPass<1>(src, srcStride, width, height, r, s); break;
	case 2: horizontalPass<2>(src, srcStride, width, height, r, s); break;
	case 3: horizontalPass<3>(src, srcStride, width, height, r, s); break;
	case 4: horizontalPass<4>(src, srcStride, width, height, r, s); break;
	case 5: horizontalPass<5>(src, srcStride, width, height, r, s); break;
	case 6: horizontalPass<6>(src, srcStride, width, height, r, s); break;
	case 7: horizontalPass<7>(src, srcStride, width, height, r, s); break;
	case 8: horizontalPass<8>(src, srcStride, width, height, r, s); break;
	default: horizontalPass<0>(src, srcStride, width, height, r, s); break;
	}
	verticalPass(s, dst, dstStride, width, height, r);
}

} // namespace kernels
} // namespace calped
