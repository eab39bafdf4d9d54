// SPDX-License-Identifier: BSD-2-Clause
// The correspondence CSV of calped-calibrate: a header "u,v,X,Y,Z", then one point per row
// (pixels, then world coordinates in the unit given on the command line).
#pragma once

#include <cstddef>
#include <vector>

#include <calped/calibration.h>

namespace calped::calibrate_tool {

struct Correspondences {
	std::vector<PointCorrespondence> points;
	std::vector<int> lines; // CSV line of each point, for the report
};

// ParseError naming `name` and the line for a missing header, a wrong field count, a
// non-numeric or non-finite field.
Status parseCorrespondences(const char *data, size_t size, const char *name,
			    Correspondences &out);

} // namespace calped::calibrate_tool
