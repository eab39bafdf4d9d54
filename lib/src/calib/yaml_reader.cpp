// SPDX-License-Identifier: BSD-2-Clause
#include "calib/yaml_reader.h"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <new>

#include "calib/text_util.h"

namespace calped::calib {

namespace {

bool isBlank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

bool isFlow(char c)
{
	return c == ',' || c == '[' || c == ']' || c == '{' || c == '}';
}

// YAML's own spellings of the non-finite values, as OpenCV writes them.
bool isYamlNonFinite(std::string_view s)
{
	std::string lower;
	for (char c : s)
		lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return lower == ".nan" || lower == ".inf" || lower == "-.inf" || lower == "+.inf";
}

bool validHeader(std::string_view line)
{
	line = trim(line);
	return line == "%YAML:1.0" || line == "%YAML 1.0" || line == "%YAML:1.1" ||
	       line == "%YAML 1.1" || line == "%YAML:1.2" || line == "%YAML 1.2";
}

} // namespace

Status YamlDocument::tokenize(std::string_view text)
{
	size_t pos = 0;
	size_t lineBegin = 0;
	int line = 1;
	bool header = false;
	bool ended = false;
	const size_t n = text.size();
	if (text.substr(0, 3) == "\xef\xbb\xbf")
		pos = lineBegin = 3;

	auto error = [&](const char *what, std::string_view arg = {}) {
		char q[kExcerptBytes + 4];
		return fileError(ErrorCode::ParseError, name_, line, what, quote(arg, q, sizeof(q)));
	};

	// The end of the current line, found once per line: finding it again for every token
	// made a line of 1M values take 66 s.
	size_t eol = 0;
	bool eolKnown = false;
	while (pos < n) {
		const char c = text[pos];
		if (c == '\n') {
			pos++;
			lineBegin = pos;
			line++;
			continue;
		}
		if (isBlank(c)) {
			pos++;
			continue;
		}
		const bool column0 = pos == lineBegin;
		if (!eolKnown || eol < pos) {
			eol = text.find('\n', pos);
			if (eol == std::string_view::npos)
				eol = n;
			eolKnown = true;
		}
		if (c == '#' && (column0 || isBlank(text[pos - 1]))) {
			pos = eol;
			continue;
		}
		if (ended)
			return error("content after the document end marker '...'");
		if (column0 && c == '%') {
			if (header || !tokens_.empty())
				return error("unexpected directive '%s'", text.substr(pos, eol - pos));
			if (!validHeader(text.substr(pos, eol - pos)))
				return error("unsupported YAML header '%s' (expected %%YAML:1.0)",
					     trim(text.substr(pos, eol - pos)));
			header = true;
			pos = eol;
			continue;
		}
		if (!header)
			return error("missing the '%%YAML:1.0' header (not an OpenCV FileStorage file?)");
		const std::string_view rest = trim(text.substr(pos, eol - pos));
		if (column0 && (rest == "---" || rest == "..." || startsWith(rest, "--- ") ||
				startsWith(rest, "... "))) {
			if (trim(stripComment(rest.substr(3))) != "")
				return error("unexpected content after '%s'", rest.substr(0, 3));
			ended = rest[0] == '.';
			pos = eol;
			continue;
		}

		YamlToken t;
		t.line = line;
		t.lineStart = column0;
		const char next = pos + 1 < n ? text[pos + 1] : '\n';
		const bool nextEnds = next == '\n' || isBlank(next) || isFlow(next);
		if (isFlow(c)) {
			t.type = c == ',' ? YamlToken::Comma
			       : c == '[' ? YamlToken::OpenBracket
			       : c == ']' ? YamlToken::CloseBracket
			       : c == '{' ? YamlToken::OpenBrace
					  : YamlToken::CloseBrace;
			pos++;
		} else if (c == ':' && nextEnds) {
			t.type = YamlToken::Colon;
			pos++;
		} else if (c == '-' && (next == '\n' || isBlank(next))) {
			return error("YAML sequences ('- item') are not supported");
		} else if (std::strchr("&*|>@`", c)) {
			return error("unsupported YAML construct '%s' (anchors, aliases, block "
				     "scalars)", text.substr(pos, 1));
		} else if (c == '!') {
			size_t e = pos;
			while (e < eol && !isBlank(text[e]) && !isFlow(text[e]))
				e++;
			t.type = YamlToken::Tag;
			t.text.assign(text.substr(pos, e - pos));
			pos = e;
		} else if (c == '"' || c == '\'') {
			size_t e = pos + 1;
			while (true) {
				if (e >= eol)
					return error("quoted string is not closed on its line");
				if (c == '"' && text[e] == '\\' && e + 1 < eol) {
					t.text += text[e + 1];
					e += 2;
					continue;
				}
				if (text[e] == c) {
					if (c == '\'' && e + 1 < eol && text[e + 1] == '\'') {
						t.text += '\'';
						e += 2;
						continue;
					}
					break;
				}
				t.text += text[e++];
			}
			t.quoted = true;
			pos = e + 1;
		} else {
			size_t e = pos;
			while (e < eol && !isBlank(text[e]) && !isFlow(text[e])) {
				if (text[e] == ':') {
					const char after = e + 1 < n ? text[e + 1] : '\n';
					if (after == '\n' || isBlank(after) || isFlow(after))
						break;
				}
				e++;
			}
			t.text.assign(text.substr(pos, e - pos));
			pos = e;
		}
		tokens_.push_back(std::move(t));
	}
	if (!header)
		return fileError(ErrorCode::ParseError, name_, 0,
				 "missing the '%%YAML:1.0' header (empty file?)");
	lastLine_ = line;
	return Status::success();
}

Status YamlDocument::split()
{
	size_t i = 0;
	while (i < tokens_.size()) {
		const YamlToken &k = tokens_[i];
		if (!(k.lineStart && k.type == YamlToken::Scalar))
			return fileError(ErrorCode::ParseError, name_, k.line,
					 "expected a top-level 'key:' at the start of the line");
		char q[kExcerptBytes + 4];
		if (i + 1 >= tokens_.size() || tokens_[i + 1].type != YamlToken::Colon)
			return fileError(ErrorCode::ParseError, name_, k.line,
					 "expected ':' after the key '%s'", quote(k.text, q, sizeof(q)));
		for (const YamlEntry &e : entries_)
			if (e.key == k.text)
				return fileError(ErrorCode::ParseError, name_, k.line,
						 "%s given twice (first on line %d)",
						 quote(k.text, q, sizeof(q)), e.line);
		YamlEntry entry;
		entry.key = k.text;
		entry.line = k.line;
		entry.begin = i + 2;
		// The value runs to the next line that starts at column 0 outside brackets.
		int depth = 0;
		size_t j = entry.begin;
		for (; j < tokens_.size(); j++) {
			const YamlToken &t = tokens_[j];
			if (t.lineStart && depth == 0)
				break;
			if (t.type == YamlToken::OpenBrace || t.type == YamlToken::OpenBracket)
				depth++;
			else if (t.type == YamlToken::CloseBrace || t.type == YamlToken::CloseBracket)
				depth--;
			if (depth < 0)
				return fileError(ErrorCode::ParseError, name_, t.line,
						 "unbalanced '%s'", t.type == YamlToken::CloseBrace ? "}" : "]");
		}
		if (depth > 0)
			return fileError(ErrorCode::ParseError, name_, lastLine_,
					 "value of '%s' (line %d) is not closed with '%s' (truncated?)",
					 quote(entry.key, q, sizeof(q)), entry.line, "]' or '}");
		entry.end = j;
		entries_.push_back(std::move(entry));
		i = j;
	}
	return Status::success();
}

Status YamlDocument::parse(const char *data, size_t size, const char *name)
{
	name_ = name;
	tokens_.clear();
	entries_.clear();
	try {
		Status st = tokenize(std::string_view(data, size));
		if (!st.ok())
			return st;
		return split();
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: out of memory reading YAML", name);
	}
}

const YamlEntry *YamlDocument::find(std::string_view key) const
{
	for (const YamlEntry &e : entries_)
		if (e.key == key)
			return &e;
	return nullptr;
}

Status YamlDocument::scalar(const YamlEntry &e, std::string &out) const
{
	if (e.end - e.begin != 1 || tokens_[e.begin].type != YamlToken::Scalar)
		return fileError(ErrorCode::ParseError, name_, e.line,
				 "'%s' must be a single value", e.key.c_str());
	out = tokens_[e.begin].text;
	return Status::success();
}

Status YamlDocument::matrix(const YamlEntry &e, Matrix &out) const
{
	const char *key = e.key.c_str();
	size_t i = e.begin;
	auto at = [&](size_t k) { return k < e.end ? &tokens_[k] : nullptr; };
	auto lineAt = [&](size_t k) { return k < e.end ? tokens_[k].line : tokens_[e.end - 1].line; };

	if (!at(i) || at(i)->type != YamlToken::Tag || at(i)->text != "!!opencv-matrix")
		return fileError(ErrorCode::ParseError, name_, e.line,
				 "'%s' must be an !!opencv-matrix", key);
	i++;
	const bool flow = at(i) && at(i)->type == YamlToken::OpenBrace;
	if (flow)
		i++;

	int rows = -1, cols = -1;
	std::string dt;
	bool haveData = false;
	std::vector<double> data;
	int dataLine = e.line;
	while (true) {
		const YamlToken *t = at(i);
		if (!t) {
			if (flow)
				return fileError(ErrorCode::ParseError, name_, lineAt(i),
						 "'%s': '{' is not closed", key);
			break;
		}
		if (flow && t->type == YamlToken::CloseBrace) {
			if (at(i + 1))
				return fileError(ErrorCode::ParseError, name_, at(i + 1)->line,
						 "'%s': unexpected content after '}'", key);
			break;
		}
		if (t->type == YamlToken::Comma) {
			i++;
			continue;
		}
		if (t->type != YamlToken::Scalar || !at(i + 1) || at(i + 1)->type != YamlToken::Colon)
			return fileError(ErrorCode::ParseError, name_, t->line,
					 "'%s': expected 'rows:', 'cols:', 'dt:' or 'data:'", key);
		const std::string field = t->text;
		const int fieldLine = t->line;
		i += 2;
		if (field == "data") {
			if (haveData)
				return fileError(ErrorCode::ParseError, name_, fieldLine,
						 "'%s': data given twice", key);
			if (!at(i) || at(i)->type != YamlToken::OpenBracket)
				return fileError(ErrorCode::ParseError, name_, lineAt(i),
						 "'%s': data must be a list '[ ... ]'", key);
			i++;
			dataLine = fieldLine;
			bool expectValue = true;
			while (true) {
				const YamlToken *v = at(i);
				if (!v)
					return fileError(ErrorCode::ParseError, name_, lineAt(i),
							 "'%s': data list is not closed with ']'", key);
				if (v->type == YamlToken::CloseBracket) {
					if (expectValue && !data.empty())
						return fileError(ErrorCode::ParseError, name_, v->line,
								 "'%s': data ends with ','", key);
					i++;
					break;
				}
				if (expectValue != (v->type == YamlToken::Scalar))
					return fileError(ErrorCode::ParseError, name_, v->line,
							 "'%s': data must be numbers separated by ','",
							 key);
				if (v->type == YamlToken::Scalar) {
					double x = 0;
					NumberResult r = parseNumber(v->text, x);
					if (r == NumberResult::NotANumber && isYamlNonFinite(v->text))
						r = NumberResult::NotFinite;
					if (r != NumberResult::Ok) {
						char label[64];
						std::snprintf(label, sizeof(label), "%s data[%zu]", key,
							      data.size());
						return numberError(r, name_, v->line, label, v->text);
					}
					data.push_back(x);
				}
				expectValue = !expectValue;
				i++;
			}
			haveData = true;
			continue;
		}
		const YamlToken *v = at(i);
		if (!v || v->type != YamlToken::Scalar) {
			char q[32];
			return fileError(ErrorCode::ParseError, name_, lineAt(i),
					 "'%s': %s needs a value", key, quote(field, q, sizeof(q)));
		}
		i++;
		if (field == "rows" || field == "cols") {
			int &target = field == "rows" ? rows : cols;
			if (target >= 0)
				return fileError(ErrorCode::ParseError, name_, fieldLine,
						 "'%s': %s given twice", key, field.c_str());
			double x = 0;
			// Range first: casting a value beyond int is undefined (found by fuzzing).
			if (parseNumber(v->text, x) != NumberResult::Ok || !(x >= 1 && x <= 64) ||
			    x != static_cast<int>(x)) {
				char q[32];
				return fileError(ErrorCode::ParseError, name_, v->line,
						 "'%s': %s '%s' is not a whole number in 1..64", key,
						 field.c_str(), quote(v->text, q, sizeof(q)));
			}
			target = static_cast<int>(x);
		} else if (field == "dt") {
			if (!dt.empty())
				return fileError(ErrorCode::ParseError, name_, fieldLine,
						 "'%s': dt given twice", key);
			dt = v->text;
			if (dt != "d" && dt != "f") {
				char q[32];
				return fileError(ErrorCode::ParseError, name_, v->line,
						 "'%s': dt '%s' is not supported (d or f)", key,
						 quote(dt, q, sizeof(q)));
			}
		} else {
			char q[32];
			return fileError(ErrorCode::ParseError, name_, fieldLine,
					 "'%s': unknown field '%s' (rows, cols, dt, data)", key,
					 quote(field, q, sizeof(q)));
		}
	}
	const char *missing = rows < 0 ? "rows" : cols < 0 ? "cols" : dt.empty() ? "dt"
			      : !haveData ? "data" : nullptr;
	if (missing)
		return fileError(ErrorCode::ParseError, name_, e.line, "'%s' lacks '%s'", key,
				 missing);
	if (data.size() != static_cast<size_t>(rows) * static_cast<size_t>(cols))
		return fileError(ErrorCode::ParseError, name_, dataLine,
				 "'%s' has %zu values in data but rows x cols = %d x %d", key,
				 data.size(), rows, cols);
	out.rows = rows;
	out.cols = cols;
	out.data.swap(data);
	return Status::success();
}

} // namespace calped::calib
