// SPDX-License-Identifier: BSD-2-Clause
#include "image_io.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.h"
#include "stb_guard.h"

// Debian's libstb ships the compiled implementations; elsewhere stb_impl.cpp provides them.
#include <stb_image.h>
#include <stb_image_write.h>

namespace calped {
namespace ports {


namespace {

struct FileCloser {
	void operator()(FILE *f) const { std::fclose(f); }
};

struct StbiFree {
	void operator()(stbi_uc *p) const { stbi_image_free(p); }
};

// stb's reason for the last failure, fit for a one-line message: stb may give none, an
// empty one, or one holding the file's raw bytes ("\x17... PNG chunk not known"); all
// three were found by fuzzing.
std::string stbReason()
{
	const char *r = stbi_failure_reason();
	const std::string reason = r ? std::string(r).substr(0, 80) : std::string();
	// stb's reasons are short ASCII words; anything else (the fuzzer saw raw high bytes
	// through a stale reason) is not quoted.
	bool printable = !reason.empty();
	for (char c : reason)
		printable = printable && static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f;
	return printable ? reason : "corrupt or unsupported image data";
}

bool startsWith(const uint8_t *data, size_t size, const char *magic, size_t length)
{
	return size >= length && std::memcmp(data, magic, length) == 0;
}

// PNG, JPEG (SOI marker) and binary PNM (P5 grey, P6 colour): the formats docs/cli.md lists.
bool documentedFormat(const uint8_t *data, size_t size)
{
	return startsWith(data, size, "\x89PNG\r\n\x1a\n", 8) || startsWith(data, size, "\xff\xd8", 2) ||
	       startsWith(data, size, "P5", 2) || startsWith(data, size, "P6", 2);
}

// What must hold before stb sees the bytes at all.
bool checkBytes(const uint8_t *data, size_t size, const std::string &path, std::string &error)
{
	if (size == 0 || size > static_cast<size_t>(INT32_MAX)) {
		error = "cannot decode " + path + (size == 0 ? ": empty file" : ": file too large");
		return false;
	}
	if (!documentedFormat(data, size)) {
		error = "cannot decode " + path + ": not a PNG, JPEG, PGM or PPM file";
		return false;
	}
	std::string reason;
	if (!safeForStb(data, size, reason)) {
		error = "cannot decode " + path + ": " + reason;
		return false;
	}
	return true;
}

bool checkSize(int width, int height, long maxPixels, const std::string &path, std::string &error)
{
	if (width <= 0 || height <= 0) {
		error = "cannot decode " + path + ": empty image";
		return false;
	}
	if (static_cast<long>(width) * height > maxPixels) {
		error = "cannot decode " + path + ": " + std::to_string(width) + " x " +
			std::to_string(height) + " pixels, the limit is " + std::to_string(maxPixels) +
			" pixels";
		return false;
	}
	return true;
}

} // namespace

namespace {

// Checks, decodes and converts to RGB8 into `pixels` (at least `capacity` bytes, or grown
// when `grow` is given).
bool decodeBytes(const uint8_t *bytes, size_t size, const std::string &path, long maxPixels,
		 std::vector<uint8_t> *grow, uint8_t *pixels, size_t capacity, int &width,
		 int &height, std::string &error)
{
	if (!checkBytes(bytes, size, path, error))
		return false;
	int w = 0, h = 0, comp = 0;
	// The header first: a few bytes may claim a huge image, and stb would allocate for it.
	if (!stbi_info_from_memory(bytes, static_cast<int>(size), &w, &h, &comp)) {
		error = "cannot decode " + path + ": " + stbReason();
		return false;
	}
	if (!checkSize(w, h, maxPixels, path, error))
		return false;
	// The file's own channel count: stb 2.27's conversion of 16-bit PNM to another count
	// overran its buffer (found by tests/fuzz/fuzz_image), so channels are mapped here.
	std::unique_ptr<stbi_uc, StbiFree> data(
		stbi_load_from_memory(bytes, static_cast<int>(size), &w, &h, &comp, 0));
	if (!data) {
		error = "cannot decode " + path + ": " + stbReason();
		return false;
	}
	if (comp < 1 || comp > 4 || !checkSize(w, h, maxPixels, path, error)) {
		if (error.empty())
			error = "cannot decode " + path + ": " + std::to_string(comp) + " channels";
		return false;
	}
	const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h);
	if (grow) {
		if (grow->size() != count * 3)
			grow->resize(count * 3); // keeps the capacity of a larger earlier frame
		pixels = grow->data();
	} else if (count * 3 > capacity) {
		// The file changed since it was probed.
		error = "cannot decode " + path + ": " + std::to_string(w) + "x" + std::to_string(h) +
			" is larger than the frame buffer (did the file change since it was probed?)";
		return false;
	}
	// Grey (1), grey + alpha (2), RGB (3), RGBA (4): grey is expanded, alpha dropped.
	const stbi_uc *in = data.get();
	uint8_t *rgb = pixels;
	for (size_t i = 0; i < count; i++, in += comp, rgb += 3) {
		if (comp < 3) {
			rgb[0] = rgb[1] = rgb[2] = in[0];
		} else {
			rgb[0] = in[0];
			rgb[1] = in[1];
			rgb[2] = in[2];
		}
	}
	width = w;
	height = h;
	return true;
}

} // namespace

bool ImageDecoder::probe(const std::string &path, int &width, int &height, std::string &error)
{
	if (!readFileBytes(path, bytes_, error, "", kMaxImageFileBytes))
		return false;
	if (!checkBytes(bytes_.data(), bytes_.size(), path, error))
		return false;
	int comp = 0;
	if (!stbi_info_from_memory(bytes_.data(), static_cast<int>(bytes_.size()), &width, &height,
				   &comp)) {
		error = "cannot decode " + path + ": " + stbReason();
		return false;
	}
	return checkSize(width, height, kMaxImagePixels, path, error);
}

bool ImageDecoder::decode(const std::string &path, RgbImage &out, std::string &error)
{
	if (!readFileBytes(path, bytes_, error, "", kMaxImageFileBytes))
		return false;
	return decodeBytes(bytes_.data(), bytes_.size(), path, kMaxImagePixels, &out.pixels, nullptr,
			   0, out.width, out.height, error);
}

bool ImageDecoder::decodeInto(const std::string &path, uint8_t *pixels, size_t capacity,
			      int &width, int &height, std::string &error)
{
	if (!readFileBytes(path, bytes_, error, "", kMaxImageFileBytes))
		return false;
	return decodeBytes(bytes_.data(), bytes_.size(), path, kMaxImagePixels, nullptr, pixels,
			   capacity, width, height, error);
}

bool probeImage(const std::string &path, int &width, int &height, std::string &error)
{
	return ImageDecoder().probe(path, width, height, error);
}

bool decodeImage(const std::string &path, RgbImage &out, std::string &error)
{
	return ImageDecoder().decode(path, out, error);
}

bool decodeImageBytes(const uint8_t *bytes, size_t size, const std::string &path, RgbImage &out,
		      std::string &error, long maxPixels)
{
	return decodeBytes(bytes, size, path, maxPixels, &out.pixels, nullptr, 0, out.width,
			   out.height, error);
}

bool writePng(const std::string &path, const RgbImage &image, std::string &error)
{
	// stb's file writer ignores fwrite's result (a full disk gave exit 0 and truncated
	// images): its callback form writes to a file whose errors commit() reports.
	AtomicFile out;
	if (!out.open(path, error))
		return false;
	const auto write = [](void *file, void *data, int size) {
		std::fwrite(data, 1, static_cast<size_t>(size), static_cast<FILE *>(file));
	};
	if (!stbi_write_png_to_func(write, out.get(), image.width, image.height, 3, image.pixels.data(),
				    image.width * 3)) {
		error = "cannot write " + path + ": PNG encoding failed";
		return false;
	}
	return out.commit(error);
}

} // namespace ports
} // namespace calped
