// SPDX-License-Identifier: BSD-2-Clause
// Small helpers the pyramid's files share.
#pragma once

#include "core/stage_clock.h"
#include "pyramid/pyramid.h"

namespace calped {
namespace pyramid_util {

// The computed level at scale 1/2, source of the smaller computed levels (as in the
// toolbox), or -1.
inline int halfLevelOf(const ModelParams &p, const ScaleList &scales)
{
	for (int i = 0; i < scales.count; i++)
		if (scales.levels[i].computed && scales.levels[i].scale == 0.5 && p.nApprox > 0)
			return i;
	return -1;
}

// Planes of one level's ten channels laid back to back in `base`.
inline void planesAt(uint16_t *base, int width, int height, Plane<uint16_t> out[kChannelCount])
{
	for (int c = 0; c < kChannelCount; c++)
		out[c] = { base + size_t(c) * width * height, width, height, width };
}

} // namespace pyramid_util
} // namespace calped
