// SPDX-License-Identifier: BSD-2-Clause
// A strict reader for the subset of YAML that OpenCV's FileStorage writes: a "%YAML:1.0"
// header, an optional "---", and top-level "key: value" entries whose values are scalars or
// "!!opencv-matrix" mappings (block or flow style) of rows, cols, dt and data: [ ... ].
// Values of keys the caller does not ask for are skipped without being interpreted.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <calped/status.h>

namespace calped::calib {

struct YamlToken {
	enum Type { Scalar, Colon, Comma, OpenBrace, CloseBrace, OpenBracket, CloseBracket, Tag };
	Type type = Scalar;
	std::string text; // scalar (unquoted) or tag
	int line = 0;
	bool lineStart = false; // first token of its line, at column 0
	bool quoted = false;
};

struct YamlEntry {
	std::string key;
	int line = 0;
	size_t begin = 0, end = 0; // value tokens [begin, end)
};

class YamlDocument
{
public:
	// Tokenises `data` and splits it into top-level entries. ParseError (file and line) for
	// anything outside the subset; duplicate keys are errors.
	Status parse(const char *data, size_t size, const char *name);

	const YamlEntry *find(std::string_view key) const;
	const std::vector<YamlEntry> &entries() const { return entries_; }

	// The entry's value as one scalar.
	Status scalar(const YamlEntry &e, std::string &out) const;

	struct Matrix {
		int rows = 0, cols = 0;
		std::vector<double> data; // row-major
	};
	// The entry's value as an "!!opencv-matrix" with dt d or f.
	Status matrix(const YamlEntry &e, Matrix &out) const;

	const char *name() const { return name_; }

private:
	Status tokenize(std::string_view text);
	Status split();

	const char *name_ = "";
	std::vector<YamlToken> tokens_;
	std::vector<YamlEntry> entries_;
	int lastLine_ = 0;
};

} // namespace calped::calib
