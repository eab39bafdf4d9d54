// SPDX-License-Identifier: BSD-2-Clause
// What ffprobe printed (the file source's size probe, ports/file/probe_output.h) on
// arbitrary bytes: accepted only as "WxH" with sides 1..16384, which print back the same.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "fuzz_checks.h"

#include "probe_output.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::ports;
	int w = -1, h = -1;
	if (!parseProbedSize(reinterpret_cast<const char *>(data), size, w, h)) {
		if (w != -1 || h != -1)
			calped::fuzz::fail("a refused answer leaves the size alone", "");
		return 0;
	}
	if (w < 1 || h < 1 || w > kMaxProbedSide || h > kMaxProbedSide)
		calped::fuzz::fail("the size is in 1..16384", "");
	char text[32];
	const int n = std::snprintf(text, sizeof(text), "%dx%d", w, h);
	if (size < size_t(n) || std::memcmp(data, text, size_t(n)) != 0)
		calped::fuzz::fail("the accepted text starts with the size it gave", text);
	return 0;
}
