// SPDX-License-Identifier: BSD-2-Clause
// Reads typed values from a fuzz input, front to back; past its end every value is 0. The
// structured targets (aravis, libcamera) build a camera's answers from it. libFuzzer's own
// FuzzedDataProvider is not used: the replay build is compiled by GCC without it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace calped::fuzz {

class Input
{
public:
	Input(const uint8_t *data, size_t size) : data_(data), size_(size) {}

	uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
	// Little-endian, `bytes` of them (1..8).
	uint64_t bits(int bytes)
	{
		uint64_t v = 0;
		for (int i = 0; i < bytes; i++)
			v |= uint64_t(u8()) << (8 * i);
		return v;
	}
	uint32_t u32() { return static_cast<uint32_t>(bits(4)); }
	uint64_t u64() { return bits(8); }

	// A number that is mostly small but may be anything: the first byte says how wide
	// (1, 2 or 4 bytes, or a full 64-bit two's complement value).
	int64_t number()
	{
		switch (u8() & 3) {
		case 0: return int64_t(bits(1));
		case 1: return int64_t(bits(2));
		case 2: return int64_t(bits(4));
		default: return static_cast<int64_t>(u64());
		}
	}

	size_t left() const { return size_ - pos_; }
	const uint8_t *rest() const { return data_ + pos_; }

private:
	const uint8_t *data_;
	size_t size_;
	size_t pos_ = 0;
};

} // namespace calped::fuzz
