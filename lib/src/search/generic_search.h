// SPDX-License-Identifier: BSD-2-Clause
// The generic method's search (Dollár's detector): the whole pyramid, and every window
// of every level.
#pragma once

#include <calped/detector.h>

#include "classify/candidates.h"
#include "classify/classifier.h"
#include "pyramid/pyramid.h"

namespace calped {

// The whole pyramid, every window; the levels are prepared and classified on the pool's
// threads (null: this one), their hits gathered in level order.
Status searchEveryWindow(FrameInput &input, Pyramid &pyramid, const Classifier &classifier, Candidates &out,
		       FrameStats &stats, ThreadPool *pool = nullptr);

} // namespace calped
