// SPDX-License-Identifier: BSD-2-Clause
// calped-convert's MAT file check (tools/convert/mat_integrity.h) on arbitrary bytes: the
// part of reading a .mat that is calped's (matio itself reads only files that passed it).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.h"

#include "mat_integrity.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	std::string error;
	const bool ok = calped::convert::checkMatIntegrity(data, size, error);
	if (!ok && !calped::fuzz::printableLine(error.c_str()))
		calped::fuzz::fail("a refusal says why on one printable line", error.c_str());
	if (ok && size < 128 + 8)
		calped::fuzz::fail("an accepted file has a header and an element", "");
	return 0;
}
