// SPDX-License-Identifier: BSD-2-Clause
// The tools' image decoding: the fuzz seeds decode to what they hold, and every input the
// image fuzz target found is refused with a reason before stb_image 2.27 mishandles it
// (tests/fuzz/regressions/image; ports/file/stb_guard.h lists the faults).
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image_io.h"
#include "test_paths.h"

namespace calped::ports {
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
	// Grey is expanded to three channels, alpha dropped.
	const Expected seeds[] = {
		{ "gray_2x2.pgm", 2, 2, { 0, 0, 0 } },
		{ "rgb_3x2.ppm", 3, 2, { 0, 1, 2 } },
		{ "gray_3x2.png", 3, 2, { 0, 0, 0 } },
		{ "rgb_4x3.png", 4, 3, { 0, 0, 0 } },
		{ "rgba_2x2.png", 2, 2, { 255, 0, 0 } },
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
	std::string error;
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
		{ "jpeg_dht_over_256_codes.jpg", "Huffman table declares 507 codes" },
		// These two reach their faults through stray bytes between segments, where stb and
		// a reader of well-formed files part ways: refused for the stray bytes.
		{ "jpeg_undefined_huffman_table.jpg", "corrupt JPEG: no marker at byte 20" },
		{ "jpeg_dht_after_fill_bytes_in_scan.jpg", "corrupt JPEG: no marker at byte 20" },
		{ "ppm_width_overflow.ppm", "width above" },
		{ "pgm_16bit_truncated.pgm", "16-bit PGM/PPM (maximum value 256) is not supported" },
		{ "pgm_16bit_complete.pgm", "16-bit PGM/PPM (maximum value 65535) is not supported" },
		{ "png_idat_2gib_length.png", "corrupt PNG: a chunk declares" },
		{ "pgm_truncated.pgm", "truncated PNM: 3 bytes of samples, 4 needed" },
		{ "png_empty_first_idat.png", "corrupt PNG: an empty IDAT chunk before the image data" },
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

// The same faults in otherwise well-formed files, made from a valid seed.
size_t findMarker(const std::vector<uint8_t> &jpeg, uint8_t marker)
{
	for (size_t i = 2; i + 1 < jpeg.size(); i++)
		if (jpeg[i] == 0xff && jpeg[i + 1] == marker)
			return i;
	return 0;
}

TEST(ImageDecode, WellFormedJpegsWithStbFaultsAreRefused)
{
	const std::vector<uint8_t> seed = bytesOf(fuzzFile("corpus/image/rgb_8x8.jpg"));
	ASSERT_GT(seed.size(), 100u);
	RgbImage image;
	std::string error;
	ASSERT_TRUE(decodeImageBytes(seed.data(), seed.size(), "seed.jpg", image, error)) << error;

	// A DHT segment of one table with 300 codes, after SOI.
	std::vector<uint8_t> big(seed.begin(), seed.begin() + 2);
	const size_t length = 2 + 17 + 300;
	const uint8_t header[] = { 0xff, 0xc4, uint8_t(length >> 8), uint8_t(length & 0xff), 0x00 };
	big.insert(big.end(), header, header + sizeof(header));
	std::vector<uint8_t> counts(16, 0);
	counts[14] = 45;
	counts[15] = 255;
	big.insert(big.end(), counts.begin(), counts.end());
	big.insert(big.end(), 300, 0x01);
	big.insert(big.end(), seed.begin() + 2, seed.end());
	EXPECT_FALSE(decodeImageBytes(big.data(), big.size(), "big.jpg", image, error));
	EXPECT_EQ(error, "cannot decode big.jpg: corrupt JPEG: a Huffman table declares 300 codes "
			 "(at most 256)");

	// The scan's first component names DC and AC table 3, which no DHT defines.
	std::vector<uint8_t> undefined = seed;
	const size_t sos = findMarker(undefined, 0xda);
	ASSERT_GT(sos, 0u);
	undefined[sos + 6] = 0x33; // FF DA, length (2), count (1), component id (1), tables
	EXPECT_FALSE(decodeImageBytes(undefined.data(), undefined.size(), "u.jpg", image, error));
	EXPECT_EQ(error, "cannot decode u.jpg: corrupt JPEG: a scan uses a Huffman table that is "
			 "not defined");

	// Cut inside a segment.
	const size_t dqt = findMarker(seed, 0xdb);
	ASSERT_GT(dqt, 0u);
	EXPECT_FALSE(decodeImageBytes(seed.data(), dqt + 10, "cut.jpg", image, error));
	EXPECT_NE(error.find("runs past the end of the file"), std::string::npos) << error;
}

// stb puts the raw bytes of an unknown PNG chunk's type into its failure reason; the
// message must stay one printable line.
TEST(ImageDecode, StbReasonsWithRawBytesAreReplaced)
{
	const std::string path = fuzzFile("regressions/image/png_unknown_chunk_raw_bytes_in_reason.png");
	RgbImage image;
	std::string error;
	EXPECT_FALSE(decodeImage(path, image, error));
	EXPECT_EQ(error, "cannot decode " + path + ": corrupt or unsupported image data");
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
} // namespace calped::ports
