// SPDX-License-Identifier: BSD-2-Clause
#include "stb_guard.h"

#include <cstring>

namespace calped::ports {

namespace {

// A cursor that reads like stb's context: bytes past the end read as 0.
struct Reader {
	const uint8_t *data;
	size_t size;
	size_t pos = 0;

	bool atEnd() const { return pos >= size; }
	int get8() { return pos < size ? data[pos++] : (pos++, 0); }
	int get16()
	{
		const int high = get8(); // two statements: the order of reads matters
		return high << 8 | get8();
	}
	void skip(long n)
	{
		if (n > 0)
			pos += static_cast<size_t>(n);
	}
};

// Next marker as stb_image's stbi__get_marker reads it: -1 when the byte is not 0xFF.
int nextMarker(Reader &r)
{
	if (r.get8() != 0xff)
		return -1;
	int m = 0xff;
	while (m == 0xff && !r.atEnd())
		m = r.get8();
	return m;
}

// Huffman tables defined so far, by class (0 DC, 1 AC) and id (0..3).
struct Tables {
	bool defined[2][4] = {};
};

// stb's DHT loop: tables are read while the declared length lasts, each table's codes
// copied before anything checks their count.
bool checkHuffmanTables(Reader &r, Tables &tables, std::string &reason)
{
	long length = r.get16() - 2;
	while (length > 0 && !r.atEnd()) {
		const int classAndId = r.get8();
		long codes = 0;
		for (int i = 0; i < 16; i++)
			codes += r.get8();
		if (codes > 256) {
			reason = "corrupt JPEG: a Huffman table declares " + std::to_string(codes) +
				 " codes (at most 256)";
			return false;
		}
		if (classAndId >> 4 <= 1 && (classAndId & 15) <= 3)
			tables.defined[classAndId >> 4][classAndId & 15] = true;
		r.skip(codes);
		length -= 17 + codes;
	}
	if (length != 0) {
		reason = "corrupt JPEG: Huffman tables do not fill their segment";
		return false;
	}
	return true;
}

// stb decodes a scan with whatever its tables hold, defined or not (they are uninitialised
// memory), indexing out of bounds: every table a scan will use must have been defined.
bool checkScanTables(Reader &r, const Tables &tables, bool progressive, std::string &reason)
{
	const size_t start = r.pos;
	const long length = r.get16();
	const int components = r.get8();
	int selectors[4] = {};
	for (int i = 0; i < components && i < 4; i++) {
		r.get8(); // component id
		selectors[i] = r.get8();
	}
	r.pos = start + 2 + 1 + 2 * static_cast<size_t>(components);
	const int spectralStart = r.get8();
	r.get8(); // spectral end
	const int approximationHigh = r.get8() >> 4;
	// Baseline scans use both tables; progressive DC scans the DC table on the first pass
	// only, AC scans the AC table.
	const bool needDc = !progressive || (spectralStart == 0 && approximationHigh == 0);
	const bool needAc = !progressive || spectralStart > 0;
	for (int i = 0; i < components && i < 4; i++) {
		const int dc = selectors[i] >> 4, ac = selectors[i] & 15;
		if ((needDc && dc <= 3 && !tables.defined[0][dc]) ||
		    (needAc && ac <= 3 && !tables.defined[1][ac])) {
			reason = "corrupt JPEG: a scan uses a Huffman table that is not defined";
			return false;
		}
	}
	r.pos = start;
	r.skip(length);
	return true;
}

// Entropy-coded data runs to the first marker; 0xFF fill bytes may precede a stuffed 0x00
// or a restart marker (stb's bit reader skips them the same way).
void skipScanData(Reader &r)
{
	while (!r.atEnd()) {
		if (r.get8() != 0xff)
			continue;
		const size_t markerStart = r.pos - 1;
		int next = r.get8();
		while (next == 0xff && !r.atEnd())
			next = r.get8();
		if (next == 0x00 || (next >= 0xd0 && next <= 0xd7))
			continue;
		r.pos = markerStart; // let nextMarker read it again
		return;
	}
}

// The segments are walked as a valid file lays them out; anything else (bytes between
// segments, a segment past the end of the file, a marker 0x00) is refused as corrupt,
// because there stb's reading and this walk could part ways. A well-formed file is read by
// stb at a subset of the places checked here (stb stops at the first surprise).
bool jpegSafe(const uint8_t *data, size_t size, std::string &reason)
{
	Reader r{ data, size, 2 };
	Tables tables;
	bool progressive = false;
	while (!r.atEnd()) {
		const size_t at = r.pos;
		const int m = nextMarker(r);
		if (m < 0 || m == 0x00 || m == 0xff) {
			reason = "corrupt JPEG: no marker at byte " + std::to_string(at);
			return false;
		}
		if (m == 0xd9)
			return true; // end of image
		if (m == 0x01 || (m >= 0xd0 && m <= 0xd8))
			continue; // markers without a length
		const size_t segment = r.pos;
		const long length = r.get16();
		if (length < 2 || static_cast<size_t>(length) > size - segment) {
			reason = "corrupt JPEG: a segment at byte " + std::to_string(at) +
				 " runs past the end of the file";
			return false;
		}
		r.pos = segment;
		if (m == 0xc4) {
			if (!checkHuffmanTables(r, tables, reason))
				return false;
			continue;
		}
		if (m == 0xc2)
			progressive = true;
		if (m == 0xda) {
			if (!checkScanTables(r, tables, progressive, reason))
				return false;
			skipScanData(r);
			continue;
		}
		r.skip(length);
	}
	return true; // a truncated file: stb decodes what there is
}

bool isPnmSpace(int c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// stbi__pnm_skip_whitespace: spaces and '#' comments up to the end of their line.
void skipPnmSpace(Reader &r, int &c)
{
	for (;;) {
		while (!r.atEnd() && isPnmSpace(c))
			c = r.get8();
		if (r.atEnd() || c != '#')
			return;
		while (!r.atEnd() && c != '\n' && c != '\r')
			c = r.get8();
	}
}

// stbi__pnm_getinteger, without its overflow: false once the value passes `limit`.
bool pnmNumber(Reader &r, int &c, long limit, long &value)
{
	value = 0;
	while (!r.atEnd() && c >= '0' && c <= '9') {
		value = value * 10 + (c - '0');
		if (value > limit)
			return false;
		c = r.get8();
	}
	return true;
}

bool pnmSafe(const uint8_t *data, size_t size, std::string &reason)
{
	Reader r{ data, size, 2 };
	int c = r.get8();
	const char *const names[3] = { "width", "height", "maximum value" };
	// stb's own limits: 2^24 pixels a side (STBI_MAX_DIMENSIONS), 16-bit samples.
	const long limits[3] = { 1L << 24, 1L << 24, 65535 };
	long values[3] = {};
	for (int i = 0; i < 3; i++) {
		skipPnmSpace(r, c);
		if (!pnmNumber(r, c, limits[i], values[i])) {
			reason = std::string("corrupt PNM header: ") + names[i] + " above " +
				 std::to_string(limits[i]);
			return false;
		}
	}
	// stb 2.27 keeps 16-bit samples in the host's byte order (on x86 and ARM the low byte
	// becomes the pixel) and overran converting their channels: 8-bit files only.
	if (values[2] > 255) {
		reason = "16-bit PGM/PPM (maximum value " + std::to_string(values[2]) +
			 ") is not supported, only 8-bit";
		return false;
	}
	// stb neither rescales other maximum values nor refuses 0: 127 would be read as a
	// darker image, silently.
	if (values[2] != 255) {
		reason = "PGM/PPM maximum value " + std::to_string(values[2]) +
			 " is not supported, only 255 (8-bit samples at full scale)";
		return false;
	}
	// stb leaves the samples of a short file uninitialised instead of failing.
	const unsigned long long samples = static_cast<unsigned long long>(values[0]) *
					   static_cast<unsigned long long>(values[1]) *
					   (data[1] == '6' ? 3 : 1);
	const size_t left = r.pos < size ? size - r.pos : 0;
	if (samples > left) {
		reason = "truncated PNM: " + std::to_string(left) + " bytes of samples, " +
			 std::to_string(samples) + " needed";
		return false;
	}
	return true;
}

// stb sizes its compressed-data buffer from each IDAT's declared length before reading it,
// so a few bytes can make it allocate gigabytes: every chunk must fit in the file.
bool pngSafe(const uint8_t *data, size_t size, std::string &reason)
{
	size_t pos = 8;
	bool imageData = false;
	while (size - pos >= 8) {
		const uint32_t length = static_cast<uint32_t>(data[pos]) << 24 |
					static_cast<uint32_t>(data[pos + 1]) << 16 |
					static_cast<uint32_t>(data[pos + 2]) << 8 | data[pos + 3];
		const size_t left = size - pos - 8; // after the length and type fields
		if (length > left) {
			reason = "corrupt PNG: a chunk declares " + std::to_string(length) +
				 " bytes but the file has " + std::to_string(left) + " left";
			return false;
		}
		if (std::memcmp(data + pos + 4, "IEND", 4) == 0)
			return true;
		// stb copies a first, empty IDAT into its still-null buffer (memcpy(NULL, ..., 0)).
		if (std::memcmp(data + pos + 4, "IDAT", 4) == 0) {
			if (length == 0 && !imageData) {
				reason = "corrupt PNG: an empty IDAT chunk before the image data";
				return false;
			}
			imageData = true;
		}
		pos += 8 + static_cast<size_t>(length);
		if (size - pos < 4)
			return true; // no CRC: stb reports the truncation itself
		pos += 4;
	}
	return true;
}

} // namespace

bool safeForStb(const uint8_t *data, size_t size, std::string &reason)
{
	if (size >= 2 && data[0] == 0xff && data[1] == 0xd8)
		return jpegSafe(data, size, reason);
	if (size >= 2 && data[0] == 'P' && (data[1] == '5' || data[1] == '6'))
		return pnmSafe(data, size, reason);
	if (size >= 8 && std::memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0)
		return pngSafe(data, size, reason);
	return true;
}

} // namespace calped::ports
