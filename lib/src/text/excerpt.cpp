// SPDX-License-Identifier: BSD-2-Clause
#include "excerpt.h"

namespace calped {

size_t utf8CharLength(const unsigned char *s, size_t left)
{
	if (left == 0)
		return 0;
	const unsigned char c = s[0];
	if (c < 0x80)
		return 1;
	size_t n = 0;
	unsigned char lo = 0x80, hi = 0xbf; // the second byte's range (Unicode table 3-7)
	if (c >= 0xc2 && c <= 0xdf)
		n = 2;
	else if (c >= 0xe0 && c <= 0xef) {
		n = 3;
		if (c == 0xe0)
			lo = 0xa0;
		else if (c == 0xed)
			hi = 0x9f;
	} else if (c >= 0xf0 && c <= 0xf4) {
		n = 4;
		if (c == 0xf0)
			lo = 0x90;
		else if (c == 0xf4)
			hi = 0x8f;
	} else {
		return 0;
	}
	if (left < n || s[1] < lo || s[1] > hi)
		return 0;
	for (size_t i = 2; i < n; i++)
		if (s[i] < 0x80 || s[i] > 0xbf)
			return 0;
	return n;
}

const char *excerpt(std::string_view text, char *out, size_t outSize, size_t maxBytes)
{
	if (outSize == 0)
		return out;
	// Room for "..." and the NUL: the excerpt shrinks to fit a small buffer.
	const size_t room = outSize > 4 ? outSize - 4 : 0;
	const size_t limit = maxBytes < room ? maxBytes : room;
	const unsigned char *s = reinterpret_cast<const unsigned char *>(text.data());
	size_t i = 0, o = 0;
	while (i < text.size()) {
		const size_t n = s[i] < 0x20 || s[i] == 0x7f ? 0 : utf8CharLength(s + i, text.size() - i);
		const size_t take = n == 0 ? 1 : n; // input bytes this character uses
		if (i + take > limit)
			break;
		if (n == 0) {
			out[o++] = '?';
		} else {
			for (size_t k = 0; k < n; k++)
				out[o++] = static_cast<char>(s[i + k]);
		}
		i += take;
	}
	if (i < text.size() && o + 3 < outSize) {
		out[o++] = '.';
		out[o++] = '.';
		out[o++] = '.';
	}
	out[o < outSize ? o : outSize - 1] = '\0';
	return out;
}

std::string excerpt(std::string_view text, size_t maxBytes)
{
	std::string out(maxBytes + 4, '\0');
	excerpt(text, &out[0], out.size(), maxBytes);
	out.resize(std::char_traits<char>::length(out.c_str()));
	return out;
}

} // namespace calped
