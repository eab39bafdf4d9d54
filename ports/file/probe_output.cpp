// SPDX-License-Identifier: BSD-2-Clause
#include "probe_output.h"

namespace calped {
namespace ports {

namespace {

// Digits at text[i...] as a number 1..kMaxProbedSide; advances i past them.
bool readSide(const char *text, size_t size, size_t &i, int &out)
{
	const size_t start = i;
	if (i < size && text[i] == '0')
		return false; // ffprobe writes no leading zero (and a side is >= 1)
	long v = 0;
	while (i < size && text[i] >= '0' && text[i] <= '9') {
		v = v * 10 + (text[i] - '0');
		if (v > kMaxProbedSide) // checked per digit: no overflow, however many digits
			return false;
		i++;
	}
	out = static_cast<int>(v);
	return i > start && v >= 1;
}

bool isSpace(char c)
{
	return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

} // namespace

bool parseProbedSize(const char *text, size_t size, int &width, int &height)
{
	size_t i = 0;
	int w = 0, h = 0;
	if (!text || !readSide(text, size, i, w) || i >= size || text[i] != 'x')
		return false;
	i++;
	if (!readSide(text, size, i, h))
		return false;
	for (; i < size; i++)
		if (!isSpace(text[i]))
			return false;
	width = w;
	height = h;
	return true;
}

} // namespace ports
} // namespace calped
