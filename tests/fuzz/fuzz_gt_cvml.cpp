// SPDX-License-Identifier: BSD-2-Clause
// calped-eval's CVML XML ground-truth reader (expat) on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.h"

#include "ground_truth.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::eval_tool;
	GroundTruth gt;
	std::string error;
	const bool ok = parseCvmlGroundTruth(reinterpret_cast<const char *>(data), size,
					     "fuzz.xml", gt, error);
	// Failure: a message and no boxes. Success may hold no box at all (frames with empty
	// object lists are a scene without people); walking them must work.
	if (!ok && !calped::fuzz::namesFile(error.c_str(), "fuzz.xml"))
		calped::fuzz::fail("the message names the file on one printable line", error.c_str());
	if (!ok && gt.lastFrame() != 0)
		calped::fuzz::fail("a failed read leaves no boxes", error.c_str());
	if (ok && gt.count(gt.lastFrame(), false) < 0)
		calped::fuzz::fail("boxes can be counted", "");
	return 0;
}
