// SPDX-License-Identifier: BSD-2-Clause
// Small integer helpers shared by the reference kernels.
#pragma once

#include <cstdint>

namespace calped {
namespace kernels {

// Round-to-nearest right shift (halves round up), for signed or unsigned values.
inline int64_t shiftRound(int64_t v, int s)
{
	return s > 0 ? (v + (int64_t(1) << (s - 1))) >> s : v << -s;
}

inline uint16_t saturateU16(int64_t v)
{
	return static_cast<uint16_t>(v < 0 ? 0 : (v > 65535 ? 65535 : v));
}

// Number of significant bits (0 for 0).
inline int bitLength(uint64_t v)
{
	return v ? 64 - __builtin_clzll(v) : 0;
}

// Split v > 0 into a 12-bit mantissa m in [2048, 4096) and an exponent k with
// v ~= m * 2^k (k may be negative for small v).
inline void normalize12(uint64_t v, int &m, int &k)
{
	k = bitLength(v) - 12;
	m = static_cast<int>(k >= 0 ? v >> k : v << -k);
}

// The same with a 13-bit mantissa m in [4096, 8192).
inline void normalize13(uint64_t v, int &m, int &k)
{
	k = bitLength(v) - 13;
	m = static_cast<int>(k >= 0 ? v >> k : v << -k);
}

// Split v into an index m < 4096 and an even exponent k with v ~= m * 2^k: exact
// (k = 0) below 1024, otherwise m >= 1024 (the square-root tables' mantissa).
inline void normalizeEven(uint64_t v, int &m, int &k)
{
	if (v < 1024) {
		m = static_cast<int>(v);
		k = 0;
		return;
	}
	k = bitLength(v) - 12;
	if (k < 0)
		k = 0;
	k += k & 1;
	m = static_cast<int>(v >> k);
}

} // namespace kernels
} // namespace calped
