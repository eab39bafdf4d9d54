// SPDX-License-Identifier: BSD-2-Clause
// calped-eval's detections-CSV reader ("frame,x,y,w,h,score", calped-detect's 9 columns)
// on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_checks.h"

#include "dets_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::eval_tool;
	SequenceDetections dets;
	std::string error;
	const bool ok = parseDetectionsCsv(std::string_view(reinterpret_cast<const char *>(data), size),
					   "fuzz.csv", 0, dets, error);
	if (!ok && !calped::fuzz::namesFile(error.c_str(), "fuzz.csv"))
		calped::fuzz::fail("the message names the file on one printable line", error.c_str());
	// Input quoted in a message is an excerpt: the message stays short whatever the field.
	if (!ok && error.size() > 400)
		calped::fuzz::fail("the message quotes a short excerpt", error.c_str());
	if (!ok && !dets.empty())
		calped::fuzz::fail("a failed read leaves no detections", error.c_str());
	if (ok && dets.size() > size_t(kMaxDetectionsCsvFrame))
		calped::fuzz::fail("the frame table is bounded", "");
	return 0;
}
