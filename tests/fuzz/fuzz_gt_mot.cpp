// SPDX-License-Identifier: BSD-2-Clause
// calped-eval's MOTChallenge gt.txt reader on arbitrary bytes.
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
	const bool ok = parseMotGroundTruth(reinterpret_cast<const char *>(data), size,
					    "fuzz.txt", gt, error);
	// Failure: a message and no boxes. Success: at least one box the harness can walk.
	if (!ok && !calped::fuzz::namesFile(error.c_str(), "fuzz.txt"))
		calped::fuzz::fail("the message names the file on one printable line", error.c_str());
	if (!ok && gt.lastFrame() != 0)
		calped::fuzz::fail("a failed read leaves no boxes", error.c_str());
	if (ok && gt.count(gt.lastFrame(), false) + gt.count(gt.lastFrame(), true) == 0)
		calped::fuzz::fail("a successful read holds a box", "");
	return 0;
}
