// SPDX-License-Identifier: BSD-2-Clause
// The generic method's search (Dollár's detector): every window of every pyramid level,
// after Pyramid::build() computed all of it.
#pragma once

#include <calped/detector.h>

#include "classify/candidates.h"
#include "classify/classifier.h"
#include "pyramid/pyramid.h"

namespace calped {

void searchEveryWindow(Pyramid &pyramid, const Classifier &classifier, Candidates &out,
		       FrameStats &stats);

} // namespace calped
