// SPDX-License-Identifier: BSD-2-Clause
#include "correspondences.h"

#include "excerpt.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <new>
#include <string>
#include <string_view>

namespace calped::calibrate_tool {

namespace {

std::string_view trim(std::string_view s)
{
	while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
		s.remove_prefix(1);
	while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
		s.remove_suffix(1);
	return s;
}

// Splits on ',' into at most `max` fields; returns the field count (max + 1 when more).
int splitFields(std::string_view line, std::string_view *fields, int max)
{
	int n = 0;
	while (true) {
		const size_t comma = line.find(',');
		if (n == max)
			return max + 1;
		fields[n++] = trim(line.substr(0, comma));
		if (comma == std::string_view::npos)
			return n;
		line.remove_prefix(comma + 1);
	}
}

bool equalsNoCase(std::string_view a, const char *b)
{
	size_t i = 0;
	for (; i < a.size() && b[i]; i++)
		if (std::tolower(static_cast<unsigned char>(a[i])) !=
		    std::tolower(static_cast<unsigned char>(b[i])))
			return false;
	return i == a.size() && !b[i];
}

// Strict decimal number: the whole field, finite.
bool toNumber(std::string_view s, double &out, bool &finite)
{
	finite = true;
	if (s.empty())
		return false;
	std::string copy(s);
	char *end = nullptr;
	const double v = std::strtod(copy.c_str(), &end);
	if (end != copy.c_str() + copy.size())
		return false;
	// strtod accepts hex and "nan"/"inf"; only decimal finite numbers are points.
	for (char c : copy)
		if (c == 'x' || c == 'X')
			return false;
	if (!std::isfinite(v)) {
		finite = false;
		return false;
	}
	out = v;
	return true;
}

const char *const kColumns[5] = { "u", "v", "X", "Y", "Z" };

} // namespace

Status parseCorrespondences(const char *data, size_t size, const char *fileName,
			    Correspondences &out)
{
	// The name and every quoted field escaped and cut (text/excerpt.h).
	char name[kExcerptPathBytes + 4];
	excerpt(fileName ? fileName : "", name, sizeof(name), kExcerptPathBytes);
	char q[kExcerptBytes + 4];
	try {
		Correspondences result;
		const std::string_view text(data, size);
		size_t pos = 0;
		int line = 0;
		bool header = false;
		while (pos < text.size()) {
			size_t eol = text.find('\n', pos);
			if (eol == std::string_view::npos)
				eol = text.size();
			const std::string_view raw = trim(text.substr(pos, eol - pos));
			pos = eol + 1;
			line++;
			if (raw.empty() || raw[0] == '#')
				continue;
			std::string_view f[5];
			const int n = splitFields(raw, f, 5);
			if (!header) {
				bool ok = n == 5;
				for (int i = 0; ok && i < 5; i++)
					ok = equalsNoCase(f[i], kColumns[i]);
				if (!ok)
					return Status::error(ErrorCode::ParseError,
							     "%s:%d: expected the header 'u,v,X,Y,Z', "
							     "found '%s'",
							     name, line, excerpt(raw, q, sizeof(q)));
				header = true;
				continue;
			}
			if (n != 5)
				return Status::error(ErrorCode::ParseError,
						     "%s:%d: expected 5 fields (u,v,X,Y,Z), found %s%d",
						     name, line, n > 5 ? "more than " : "", n > 5 ? 5 : n);
			double v[5];
			for (int i = 0; i < 5; i++) {
				bool finite = true;
				if (!toNumber(f[i], v[i], finite))
					return Status::error(ErrorCode::ParseError,
							     "%s:%d: %s '%s' is not a %snumber", name,
							     line, kColumns[i], excerpt(f[i], q, sizeof(q)),
							     finite ? "" : "finite ");
			}
			PointCorrespondence p;
			p.image = Eigen::Vector2d(v[0], v[1]);
			p.world = Eigen::Vector3d(v[2], v[3], v[4]);
			result.points.push_back(p);
			result.lines.push_back(line);
		}
		if (!header)
			return Status::error(ErrorCode::ParseError,
					     "%s: empty (expected the header 'u,v,X,Y,Z' and points)",
					     name);
		out = std::move(result);
		return Status::success();
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: out of memory", name);
	}
}

} // namespace calped::calibrate_tool
