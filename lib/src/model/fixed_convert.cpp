// SPDX-License-Identifier: BSD-2-Clause
#include "model/fixed_convert.h"

#include <cmath>
#include <limits>

namespace calped {

namespace {

int32_t clampToInt32(double v)
{
	if (v <= static_cast<double>(std::numeric_limits<int32_t>::min()))
		return std::numeric_limits<int32_t>::min();
	if (v >= static_cast<double>(std::numeric_limits<int32_t>::max()))
		return std::numeric_limits<int32_t>::max();
	return static_cast<int32_t>(v);
}

} // namespace

int32_t thresholdToFixed(double threshold)
{
	// "q < NaN" is false for every q, and so is "q < INT32_MIN" for every int32 q.
	if (std::isnan(threshold))
		return std::numeric_limits<int32_t>::min();
	// Multiplying by a power of two is exact in double, so q/2^14 < t <=> q < t*2^14, and for
	// an integer q that is q < ceil(t*2^14) whether or not t*2^14 is itself an integer.
	const double scaled = std::ldexp(threshold, kChannelFracBits);
	return clampToInt32(std::ceil(scaled));
}

int32_t leafValueToFixed(double value)
{
	if (std::isnan(value))
		return 0;
	return clampToInt32(std::round(std::ldexp(value, kScoreFracBits)));
}

int32_t filterWeightToFixed(double value)
{
	if (std::isnan(value))
		return 0;
	return clampToInt32(std::round(std::ldexp(value, kFilterFracBits)));
}

} // namespace calped
