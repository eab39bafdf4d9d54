// SPDX-License-Identifier: BSD-2-Clause
// The tools' image decoding (stb_image through ports/file/image_io) on arbitrary bytes.
// The pixel cap is lower than the tools' so one input cannot spend seconds decoding a
// huge frame; the code path is the same.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_checks.h"

#include "image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	using namespace calped::ports;
	RgbImage image;
	std::string error;
	const bool ok = decodeImageBytes(data, size, "fuzz.img", image, error, 1L << 20);
	if (!ok && !calped::fuzz::namesFile(error.c_str(), "fuzz.img"))
		calped::fuzz::fail("the message names the file on one printable line", error.c_str());
	if (ok && (image.width <= 0 || image.height <= 0 ||
		   image.pixels.size() != size_t(image.width) * size_t(image.height) * 3))
		calped::fuzz::fail("a decoded image has its size", "");
	return 0;
}
