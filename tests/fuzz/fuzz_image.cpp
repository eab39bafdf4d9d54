// SPDX-License-Identifier: BSD-2-Clause
// The tools' image decoding (stb_image through ports/file/image_io) on arbitrary bytes.
// The pixel cap is lower than the tools' so one input cannot spend long decoding a huge
// frame; the code path is the same (the cap is checked from the header, before decoding).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.h"

#include "image_io.h"

namespace {

// 2^20 pixels when replaying (tests/fuzz/replay_main.cpp: the seeds and regressions, one
// of which is a 2048x283 JPEG); 2^16 under libFuzzer, which calls LLVMFuzzerInitialize:
// decoding a 2^20-pixel JPEG under ASan and coverage took most of the run (about 1,200
// inputs a second), 2^16 pixels decode twenty times as many.
long maxPixels = 1L << 20;

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
	maxPixels = 1L << 16;
	return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::ports;
	RgbImage image;
	std::string error;
	const bool ok = decodeImageBytes(data, size, "fuzz.img", image, error, maxPixels);
	if (!ok && !calped::fuzz::namesFile(error.c_str(), "fuzz.img"))
		calped::fuzz::fail("the message names the file on one printable line", error.c_str());
	if (ok && (image.width <= 0 || image.height <= 0 ||
		   image.pixels.size() != size_t(image.width) * size_t(image.height) * 3))
		calped::fuzz::fail("a decoded image has its size", "");
	return 0;
}
