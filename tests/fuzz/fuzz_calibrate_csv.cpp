// SPDX-License-Identifier: BSD-2-Clause
// calped-calibrate's correspondence CSV ("u,v,X,Y,Z") on arbitrary bytes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_checks.h"

#include "correspondences.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::calibrate_tool;
	Correspondences c;
	const calped::Status st = parseCorrespondences(reinterpret_cast<const char *>(data), size,
						       "fuzz.csv", c);
	if (!st.ok() && !calped::fuzz::namesFile(st.message(), "fuzz.csv"))
		calped::fuzz::fail("the message names the file on one printable line", st.message());
	if (!st.ok() && !c.points.empty())
		calped::fuzz::fail("a failed read leaves no points", st.message());
	if (st.ok() && c.points.size() != c.lines.size())
		calped::fuzz::fail("each point has its line", "");
	for (const auto &p : c.points)
		if (!p.image.allFinite() || !p.world.allFinite())
			calped::fuzz::fail("points are finite", "");
	return 0;
}
