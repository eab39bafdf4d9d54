// SPDX-License-Identifier: BSD-2-Clause
// Small NEON helpers shared by the ARM kernels. One source for armv7 (with -mfpu=neon) and
// aarch64: where A64 has a better instruction, a helper picks it under __aarch64__.
#pragma once

#include <arm_neon.h>

#include <cstdint>

// For the per-block helpers called in the kernels' inner loops: inlined, their constants
// (table coefficients, masks) are set up once per row instead of once per call.
#define CALPED_NEON_INLINE inline __attribute__((always_inline))

namespace calped {
namespace kernels {
namespace {

// Number of significant bits of each lane (0 for 0).
inline int32x4_t bitLength4(uint32x4_t v)
{
	return vsubq_s32(vdupq_n_s32(32), vreinterpretq_s32_u32(vclzq_u32(v)));
}

// NEON has no gather: table reads go through the scalar unit, four lanes at a time.
inline uint32x4_t lookup4(const uint16_t *table, int32x4_t index)
{
	int32_t i[4];
	vst1q_s32(i, index);
	const uint32_t v[4] = { table[i[0]], table[i[1]], table[i[2]], table[i[3]] };
	return vld1q_u32(v);
}

inline uint32x4_t lookup4(const uint32_t *table, int32x4_t index)
{
	int32_t i[4];
	vst1q_s32(i, index);
	const uint32_t v[4] = { table[i[0]], table[i[1]], table[i[2]], table[i[3]] };
	return vld1q_u32(v);
}

// Entries of a table of 64-bit pairs, split: val[0] the low 32 bits of each lane's entry,
// val[1] the high ones (vld2 de-interleaves the little-endian halves).
inline uint32x4x2_t lookupPairs4(const uint64_t *table, int32x4_t index)
{
	int32_t i[4];
	vst1q_s32(i, index);
	const uint64_t v[4] = { table[i[0]], table[i[1]], table[i[2]], table[i[3]] };
	return vld2q_u32(reinterpret_cast<const uint32_t *>(v));
}

// Sixteen bytes picked from the 32 of `table` by byte indices below 32.
inline uint8x16_t lookupBytes32(uint8x16x2_t table, uint8x16_t index)
{
#if defined(__aarch64__)
	return vqtbl2q_u8(table, index);
#else
	const uint8x8x4_t t = { { vget_low_u8(table.val[0]), vget_high_u8(table.val[0]),
				  vget_low_u8(table.val[1]), vget_high_u8(table.val[1]) } };
	return vcombine_u8(vtbl4_u8(t, vget_low_u8(index)), vtbl4_u8(t, vget_high_u8(index)));
#endif
}

// Sums of neighbouring lanes: a0 + a1, a2 + a3, b0 + b1, b2 + b3.
inline uint32x4_t pairSums(uint32x4_t a, uint32x4_t b)
{
#if defined(__aarch64__)
	return vpaddq_u32(a, b);
#else
	return vcombine_u32(vpadd_u32(vget_low_u32(a), vget_high_u32(a)),
			    vpadd_u32(vget_low_u32(b), vget_high_u32(b)));
#endif
}

// The sums of all four lanes of a, b, c and d, in that order.
inline uint32x4_t horizontalSums4(uint32x4_t a, uint32x4_t b, uint32x4_t c, uint32x4_t d)
{
	return pairSums(pairSums(a, b), pairSums(c, d));
}

// The sums of all four lanes of a and of b.
inline uint32x2_t laneSums2(uint32x4_t a, uint32x4_t b)
{
	const uint32x4_t p = pairSums(a, b);
	return vpadd_u32(vget_low_u32(p), vget_high_u32(p));
}

} // namespace
} // namespace kernels
} // namespace calped
