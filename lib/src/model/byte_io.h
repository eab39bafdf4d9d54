// SPDX-License-Identifier: BSD-2-Clause
// Little-endian byte packing for the model blob. Values are assembled byte by byte so the
// layout does not depend on the host's endianness, alignment or struct padding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace calped {

inline uint32_t readLe32(const uint8_t *p)
{
	return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
	       static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

inline uint64_t readLe64(const uint8_t *p)
{
	return static_cast<uint64_t>(readLe32(p)) | static_cast<uint64_t>(readLe32(p + 4)) << 32;
}

inline void writeLe32(uint8_t *p, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		p[i] = static_cast<uint8_t>(v >> (8 * i));
}

inline uint32_t floatBits(float f)
{
	uint32_t u;
	std::memcpy(&u, &f, sizeof(u));
	return u;
}

inline float floatFromBits(uint32_t u)
{
	float f;
	std::memcpy(&f, &u, sizeof(f));
	return f;
}

// Appends little-endian values to a byte vector.
class ByteWriter
{
public:
	explicit ByteWriter(std::vector<uint8_t> &out) : out_(out) {}

	void u8(uint8_t v) { out_.push_back(v); }
	void u32(uint32_t v)
	{
		for (int i = 0; i < 4; i++)
			out_.push_back(static_cast<uint8_t>(v >> (8 * i)));
	}
	void u64(uint64_t v)
	{
		u32(static_cast<uint32_t>(v));
		u32(static_cast<uint32_t>(v >> 32));
	}
	void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
	void f32(float v) { u32(floatBits(v)); }
	void bytes(const void *data, size_t size)
	{
		const uint8_t *p = static_cast<const uint8_t *>(data);
		out_.insert(out_.end(), p, p + size);
	}

private:
	std::vector<uint8_t> &out_;
};

// Reads little-endian values from a buffer; every read checks the remaining length and
// returns false (leaving the value untouched) instead of reading past the end.
class ByteReader
{
public:
	ByteReader(const uint8_t *data, size_t size) : data_(data), size_(size) {}

	size_t remaining() const { return size_ - pos_; }

	bool u32(uint32_t &v)
	{
		if (remaining() < 4)
			return false;
		v = readLe32(data_ + pos_);
		pos_ += 4;
		return true;
	}
	bool i32(int32_t &v)
	{
		uint32_t u;
		if (!u32(u))
			return false;
		v = static_cast<int32_t>(u);
		return true;
	}
	bool f32(float &v)
	{
		uint32_t u;
		if (!u32(u))
			return false;
		v = floatFromBits(u);
		return true;
	}
	// Points at the next `size` bytes and skips them; null if fewer remain.
	const uint8_t *take(size_t size)
	{
		if (remaining() < size)
			return nullptr;
		const uint8_t *p = data_ + pos_;
		pos_ += size;
		return p;
	}

private:
	const uint8_t *data_;
	size_t size_;
	size_t pos_ = 0;
};

} // namespace calped
