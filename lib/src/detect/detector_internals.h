// SPDX-License-Identifier: BSD-2-Clause
// Tests' access to a Detector's stages (not installed; the public API has none of it).
#pragma once

#include <calped/detector.h>

#include "detect/detector_impl.h"

namespace calped {

class DetectorInternals
{
public:
	static DetectorImpl &of(Detector &d) { return *d.impl_; }
};

} // namespace calped
