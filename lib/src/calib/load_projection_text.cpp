// SPDX-License-Identifier: BSD-2-Clause
// Plain projection matrix text: three rows of four numbers (spaces or commas between them),
// '#' comments, blank lines, and at most one "unit: mm|cm|m" line (metres when absent).
#include <calped/calibration.h>

#include <cstdio>
#include <new>
#include <string_view>

#include "calib/text_util.h"

namespace calped {

namespace {

bool isSeparator(char c)
{
	return c == ' ' || c == '\t' || c == ',';
}

} // namespace

Status loadProjectionText(const char *data, size_t size, const char *name, CameraModel &out)
{
	using calib::fileError;
	Matrix34d P;
	int rows = 0;
	int rowLine[3] = {};
	LengthUnit unit = LengthUnit::Metre;
	int unitLine = 0;

	calib::LineReader lines(data, size);
	std::string_view line;
	while (lines.next(line)) {
		const int n = lines.lineNumber();
		const std::string_view text = calib::trim(calib::stripComment(line));
		if (text.empty())
			continue;
		char q[kExcerptBytes + 4];
		if (calib::startsWith(text, "unit")) {
			const size_t colon = text.find(':');
			if (colon == std::string_view::npos || calib::trim(text.substr(0, colon)) != "unit")
				return fileError(ErrorCode::ParseError, name, n,
						 "expected 'unit: mm|cm|m', found '%s'",
						 calib::quote(text, q, sizeof(q)));
			if (unitLine)
				return fileError(ErrorCode::ParseError, name, n,
						 "unit given twice (first on line %d)", unitLine);
			const std::string_view u = calib::trim(text.substr(colon + 1));
			if (!parseLengthUnit(u.data(), u.size(), unit))
				return fileError(ErrorCode::ParseError, name, n,
						 "unknown unit '%s' (expected mm, cm or m)",
						 calib::quote(u, q, sizeof(q)));
			unitLine = n;
			continue;
		}
		if (rows == 3)
			return fileError(ErrorCode::ParseError, name, n,
					 "more than 3 rows: P is 3x4 (rows on lines %d, %d, %d)",
					 rowLine[0], rowLine[1], rowLine[2]);
		int cols = 0;
		size_t pos = 0;
		while (pos < text.size()) {
			while (pos < text.size() && isSeparator(text[pos]))
				pos++;
			if (pos == text.size())
				break;
			size_t end = pos;
			while (end < text.size() && !isSeparator(text[end]))
				end++;
			const std::string_view token = text.substr(pos, end - pos);
			pos = end;
			if (cols == 4) {
				cols++;
				break;
			}
			double v = 0;
			const calib::NumberResult r = calib::parseNumber(token, v);
			if (r != calib::NumberResult::Ok) {
				char field[32];
				std::snprintf(field, sizeof(field), "P(%d,%d)", rows + 1, cols + 1);
				return calib::numberError(r, name, n, field, token);
			}
			P(rows, cols++) = v;
		}
		if (cols != 4)
			return fileError(ErrorCode::ParseError, name, n,
					 "row %d has %s4 numbers: P is 3x4", rows + 1,
					 cols < 4 ? "fewer than " : "more than ");
		rowLine[rows++] = n;
	}
	if (rows == 0)
		return fileError(ErrorCode::ParseError, name, 0,
				 "no matrix rows: expected 3 rows of 4 numbers");
	if (rows < 3)
		return fileError(ErrorCode::ParseError, name, lines.lineNumber(),
				 "only %d row%s: P is 3x4 (truncated?)", rows, rows == 1 ? "" : "s");
	return calib::withFileName(CameraModel::fromProjection(P, unit, out), name);
}

Status formatProjectionText(const Matrix34d &P, LengthUnit unit, const std::string &comment,
			    std::string &out)
{
	if (!P.allFinite())
		return Status::error(ErrorCode::InvalidArgument, "projection matrix is not finite");
	try {
		std::string s;
		size_t start = 0;
		while (start < comment.size()) {
			size_t end = comment.find('\n', start);
			if (end == std::string::npos)
				end = comment.size();
			s += "# ";
			s.append(comment, start, end - start);
			s += '\n';
			start = end + 1;
		}
		s += "unit: ";
		s += lengthUnitName(unit);
		s += '\n';
		for (int r = 0; r < 3; r++) {
			char row[160];
			std::snprintf(row, sizeof(row), "%.17g %.17g %.17g %.17g\n", P(r, 0), P(r, 1),
				      P(r, 2), P(r, 3));
			s += row;
		}
		out.swap(s);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "formatting the projection matrix");
	}
	return Status::success();
}

} // namespace calped
