// SPDX-License-Identifier: BSD-2-Clause
// --dump-arrays: the raw clf arrays as text, in the layout of the toolbox reference dumps
// (one line per node, one space-separated column per tree).
#pragma once

#include <string>

#include <calped/status.h>

#include "detector_clf.h"

namespace calped {
namespace convert {

// Writes DIR/<name>.txt for each array (creating DIR if needed). Integers print exactly,
// single-precision values with %.9g (enough to round-trip a float), doubles with %.17g.
Status dumpArrays(const RawClf &clf, const std::string &dir);

} // namespace convert
} // namespace calped
