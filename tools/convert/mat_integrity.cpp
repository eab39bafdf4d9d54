// SPDX-License-Identifier: BSD-2-Clause
#include "mat_integrity.h"

#include <cstring>
#include <vector>

#include <zlib.h>

namespace calped {
namespace convert {

namespace {

constexpr size_t kHeaderBytes = 128;
constexpr uint32_t kMiMatrix = 14, kMiCompressed = 15;

uint32_t word(const uint8_t *p, bool swap)
{
	uint32_t v;
	std::memcpy(&v, p, 4);
	return swap ? __builtin_bswap32(v) : v;
}

// Inflates the whole zlib stream, output dropped: Z_STREAM_END only after the Adler-32
// checksum matched, and the stream must end exactly at the element's end.
bool inflatesCompletely(const uint8_t *data, size_t size, std::string &error)
{
	z_stream z{};
	if (inflateInit(&z) != Z_OK) {
		error = "cannot start zlib";
		return false;
	}
	std::vector<uint8_t> scratch(65536);
	z.next_in = const_cast<Bytef *>(data);
	z.avail_in = static_cast<uInt>(size);
	int rc = Z_OK;
	size_t out = 0;
	while (rc == Z_OK) {
		z.next_out = scratch.data();
		z.avail_out = static_cast<uInt>(scratch.size());
		rc = inflate(&z, Z_NO_FLUSH);
		out += scratch.size() - z.avail_out;
		if (out > kMaxInflatedBytes) {
			inflateEnd(&z);
			error = "inflates to more than " + std::to_string(kMaxInflatedBytes) + " bytes";
			return false;
		}
		if (rc == Z_BUF_ERROR && z.avail_in == 0)
			break; // input ended before the stream did
	}
	const size_t left = z.avail_in;
	inflateEnd(&z);
	if (rc != Z_STREAM_END) {
		error = rc == Z_DATA_ERROR ? std::string("is corrupt (zlib: ") + (z.msg ? z.msg : "bad data") + ")"
					   : "ends inside its compressed stream (truncated)";
		return false;
	}
	if (left != 0) {
		error = "has " + std::to_string(left) + " bytes after its compressed stream";
		return false;
	}
	return true;
}

} // namespace

bool checkMatIntegrity(const uint8_t *data, size_t size, std::string &error)
{
	if (size < kHeaderBytes || std::memcmp(data, "MATLAB 5.0 MAT-file", 19) != 0) {
		error = "not a MAT file (Matlab v5): no 128-byte header starting 'MATLAB 5.0 MAT-file'";
		return false;
	}
	// The endian indicator "IM" (as written on a little-endian machine) or "MI".
	const bool little = data[126] == 'I' && data[127] == 'M';
	if (!little && !(data[126] == 'M' && data[127] == 'I')) {
		error = "header's endian indicator is neither 'IM' nor 'MI'";
		return false;
	}
	const bool swap = little != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
	size_t pos = kHeaderBytes;
	int index = 0;
	if (pos == size) {
		error = "holds no variable";
		return false;
	}
	while (pos < size) {
		index++;
		const std::string where = "element " + std::to_string(index) + " at byte " + std::to_string(pos);
		if (size - pos < 8) {
			error = where + ": " + std::to_string(size - pos) + " bytes, not a whole tag (truncated)";
			return false;
		}
		const uint32_t type = word(data + pos, swap), length = word(data + pos + 4, swap);
		if (type != kMiMatrix && type != kMiCompressed) {
			error = where + ": type " + std::to_string(type) + " is not a variable (14) or a compressed one (15)";
			return false;
		}
		const size_t body = pos + 8;
		if (length > size - body) {
			error = where + ": declares " + std::to_string(length) + " bytes, the file has " +
				std::to_string(size - body) + " after its tag (truncated)";
			return false;
		}
		if (type == kMiCompressed) {
			std::string why;
			if (!inflatesCompletely(data + body, length, why)) {
				error = where + ": the compressed variable " + why;
				return false;
			}
			pos = body + length;
		} else {
			// Uncompressed variables are padded to 8 bytes.
			const size_t padded = (size_t(length) + 7) & ~size_t(7);
			if (padded > size - body) {
				error = where + ": its padding runs past the end of the file (truncated)";
				return false;
			}
			pos = body + padded;
		}
	}
	return true;
}

} // namespace convert
} // namespace calped
