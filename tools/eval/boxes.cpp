// SPDX-License-Identifier: BSD-2-Clause
#include "boxes.h"

#include <algorithm>

namespace calped::eval_tool {

double intersectionOverUnion(const Box &a, const Box &b)
{
	if (!(a.w > 0 && a.h > 0 && b.w > 0 && b.h > 0))
		return 0.0;
	const double iw = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
	const double ih = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
	if (iw <= 0 || ih <= 0)
		return 0.0;
	const double inter = iw * ih;
	return inter / (a.w * a.h + b.w * b.h - inter);
}

} // namespace calped::eval_tool
