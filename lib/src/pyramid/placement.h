// SPDX-License-Identifier: BSD-2-Clause
// Beyond the toolbox, for the calibrated mode: where to compute channels when only some
// pyramid levels, and only some rows of each, are needed. The toolbox computes every
// octave of the frame (1, 1/2, 1/4, ...) and approximates the levels between; when the
// needed levels start below an octave, that octave is computed in all the rows its
// approximated neighbours read, mostly for their sake. Placing the computed levels among
// the needed ones instead, each no further from the levels it serves than the toolbox's
// own reach, computes far fewer pixels (docs/calibrated.md).
#pragma once

#include <calped/model.h>

#include "pyramid/cell_range.h"
#include "pyramid/scales.h"

namespace calped {

// How far (in levels) the toolbox approximates a level from its computed source: half of
// the nApprox + 1 levels between computed levels, rounded up (4 for the INRIA model).
int toolboxReach(const ModelParams &p);

// The computed levels and sources (source[i] == i: computed) that serve every needed
// level (non-empty band in levelRows, rows of the level before padding) from a computed
// level at most `reach` levels away, with the fewest channel pixels computed: each
// computed level in the rows its own and its approximated levels' bands need,
// `channelMargin` LUV rows wider on each side. Levels nobody needs are never computed
// (their source is the nearest computed level), nor levels too small to be resampled
// from the imageWidth x imageHeight image in one step. False, and nothing written, when
// no level is needed, the model computes every level (nApprox = 0) or some needed level
// has no computable level within reach. Allocates (setup time only).
bool choosePlacedLevels(const ModelParams &p, const ScaleList &scales,
			  const CellRange *levelRows, int channelMargin, int reach, int imageWidth,
			  int imageHeight, int *source);

// Mark the computed levels and sources of `scales` as choosePlacedLevels() gave them.
void applyPlacedLevels(ScaleList &scales, const int *source);

// Channel pixels (LUV rows x width) the computed levels of `scales` need for these
// bands, computed levels as marked in `scales` with their sources; for comparisons.
double computedPixels(const ModelParams &p, const ScaleList &scales, const CellRange *levelRows,
		      int channelMargin);

} // namespace calped
