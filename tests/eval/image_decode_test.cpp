// SPDX-License-Identifier: BSD-2-Clause
// The tools' image decoding: the fuzz seeds decode to what they hold, and every input the
// image fuzz target found is refused with a reason before stb_image 2.27 mishandles it
// (tests/fuzz/regressions/image; tools/detect/stb_guard.h lists the faults).
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image_io.h"
#include "test_paths.h"

namespace calped::detect_tool {
namespace {

std::string fuzzFile(const std::string &relative)
{
	return eval_tool::test::envOr("CALPED_SOURCE_DIR", ".") + "/tests/fuzz/" + relative;
}

std::vector<uint8_t> bytesOf(const std::string &path)
{
	std::vector<uint8_t> bytes;
	if (FILE *f = std::fopen(path.c_str(), "rb")) {
		int c;
		while ((c = std::fgetc(f)) != EOF)
			bytes.push_back(static_cast<uint8_t>(c));
		std::fclose(f);
	}
	return bytes;
}

struct Expected {
	const char *file;
	int width, height;
	uint8_t firstPixel[3];
};

TEST(ImageDecode, SeedsDecodeToTheirPixels)
{
	// Grey is expanded to three channels, alpha dropped, 16-bit samples keep their top byte.
	const Expected seeds[] = {
		{ "gray_2x2.pgm", 2, 2, { 0, 0, 0 } },
		{ "rgb_3x2.ppm", 3, 2, { 0, 1, 2 } },
		{ "gray_3x2.png", 3, 2, { 0, 0, 0 } },
		{ "rgb_4x3.png", 4, 3, { 0, 0, 0 } },
		{ "rgba_2x2.png", 2, 2, { 255, 0, 0 } },
		{ "gray16_1x2.pgm", 1, 2, { 0x10, 0x10, 0x10 } },
		{ "rgb16_2x1.ppm", 2, 1, { 1, 2, 3 } },
	};
	for (const Expected &e : seeds) {
		const std::string path = fuzzFile(std::string("corpus/image/") + e.file);
		RgbImage image;
		std::string error;
		ASSERT_TRUE(decodeImage(path, image, error)) << error;
		EXPECT_EQ(image.width, e.width) << e.file;
		EXPECT_EQ(image.height, e.height) << e.file;
		ASSERT_EQ(image.pixels.size(), size_t(e.width) * e.height * 3) << e.file;
		for (int c = 0; c < 3; c++)
			EXPECT_EQ(image.pixels[c], e.firstPixel[c]) << e.file << " channel " << c;
	}
	// The second sample of the 16-bit grey seed is 0xABCD.
	RgbImage gray16;
	std::string error;
	ASSERT_TRUE(decodeImage(fuzzFile("corpus/image/gray16_1x2.pgm"), gray16, error)) << error;
	EXPECT_EQ(gray16.pixels[3], 0xab);
	EXPECT_EQ(gray16.pixels[5], 0xab);
	// JPEG is lossy: only the size is certain.
	for (const char *jpeg : { "rgb_8x8.jpg", "gray_8x8.jpg" }) {
		RgbImage image;
		ASSERT_TRUE(decodeImage(fuzzFile(std::string("corpus/image/") + jpeg), image, error))
			<< error;
		EXPECT_EQ(image.width, 8);
		EXPECT_EQ(image.height, 8);
	}
}

TEST(ImageDecode, FuzzFindingsAreRefusedWithAReason)
{
	const struct {
		const char *file;
		const char *reason;
	} findings[] = {
		{ "jpeg_dht_over_256_codes.jpg", "Huffman table declares" },
		{ "jpeg_undefined_huffman_table.jpg", "Huffman table that is not defined" },
		{ "ppm_width_overflow.ppm", "width above" },
		{ "pgm_16bit_truncated.pgm", "truncated PNM" },
		{ "png_idat_2gib_length.png", "chunk declares 2147483648 bytes" },
	};
	for (const auto &f : findings) {
		const std::string path = fuzzFile(std::string("regressions/image/") + f.file);
		ASSERT_FALSE(bytesOf(path).empty()) << path;
		RgbImage image;
		std::string error;
		EXPECT_FALSE(decodeImage(path, image, error)) << f.file;
		EXPECT_NE(error.find(path), std::string::npos) << error;
		EXPECT_NE(error.find(f.reason), std::string::npos) << f.file << ": " << error;
		int w = 0, h = 0;
		EXPECT_FALSE(probeImage(path, w, h, error)) << f.file;
	}
}

TEST(ImageDecode, RefusesFormatsAndSizesOutsideTheDocumentedOnes)
{
	RgbImage image;
	std::string error;
	const uint8_t gif[] = { 'G', 'I', 'F', '8', '9', 'a', 1, 0, 1, 0, 0, 0, 0, ';' };
	EXPECT_FALSE(decodeImageBytes(gif, sizeof(gif), "x.gif", image, error));
	EXPECT_NE(error.find("not a PNG, JPEG, PGM or PPM"), std::string::npos) << error;
	// 3 x 2 pixels are fine under a limit of 6 pixels and refused under 5.
	const std::vector<uint8_t> ppm = bytesOf(fuzzFile("corpus/image/rgb_3x2.ppm"));
	EXPECT_TRUE(decodeImageBytes(ppm.data(), ppm.size(), "p.ppm", image, error, 6)) << error;
	EXPECT_FALSE(decodeImageBytes(ppm.data(), ppm.size(), "p.ppm", image, error, 5));
	EXPECT_NE(error.find("3 x 2 pixels, the limit is 5"), std::string::npos) << error;
}

} // namespace
} // namespace calped::detect_tool
