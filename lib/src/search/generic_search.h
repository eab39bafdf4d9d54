// SPDX-License-Identifier: BSD-2-Clause
// The generic method's search (Dollár's detector): the whole pyramid, and every window
// of every level.
#pragma once

#include <calped/detector.h>

#include "classify/candidates.h"
#include "classify/classifier.h"
#include "pyramid/pyramid.h"

namespace calped {

Status searchEveryWindow(FrameInput &input, Pyramid &pyramid, const Classifier &classifier, Candidates &out,
		       FrameStats &stats);

} // namespace calped
