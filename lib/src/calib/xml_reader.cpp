// SPDX-License-Identifier: BSD-2-Clause
#include "calib/xml_reader.h"

#include <cstdarg>
#include <cstdio>
#include <new>
#include <string_view>
#include <unordered_set>

#include "calib/text_util.h"

namespace calped::calib {

const XmlAttribute *XmlElement::attribute(std::string_view attrName) const
{
	for (const XmlAttribute &a : attributes)
		if (a.name == attrName)
			return &a;
	return nullptr;
}

namespace {

bool isSpace(char c)
{
	return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool isNameStart(char c)
{
	return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':';
}

bool isNameChar(char c)
{
	return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

void appendUtf8(std::string &s, unsigned long cp)
{
	if (cp < 0x80) {
		s += static_cast<char>(cp);
	} else if (cp < 0x800) {
		s += static_cast<char>(0xc0 | (cp >> 6));
		s += static_cast<char>(0x80 | (cp & 0x3f));
	} else if (cp < 0x10000) {
		s += static_cast<char>(0xe0 | (cp >> 12));
		s += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
		s += static_cast<char>(0x80 | (cp & 0x3f));
	} else {
		s += static_cast<char>(0xf0 | (cp >> 18));
		s += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
		s += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
		s += static_cast<char>(0x80 | (cp & 0x3f));
	}
}

class Parser
{
public:
	Parser(const char *data, size_t size, const char *name)
		: text_(data, size), name_(name)
	{
	}

	Status run(std::vector<XmlElement> &out);

private:
	bool atEnd() const { return pos_ >= text_.size(); }
	char peek(size_t ahead = 0) const
	{
		return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
	}
	bool lookingAt(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
	void advance(size_t n = 1)
	{
		for (size_t i = 0; i < n && pos_ < text_.size(); i++, pos_++)
			if (text_[pos_] == '\n')
				line_++;
	}
	void skipSpace()
	{
		while (!atEnd() && isSpace(peek()))
			advance();
	}

#if defined(__GNUC__)
	[[gnu::format(printf, 2, 3)]]
#endif
	Status error(const char *fmt, ...) const
	{
		char msg[160];
		va_list args;
		va_start(args, fmt);
		std::vsnprintf(msg, sizeof(msg), fmt, args);
		va_end(args);
		return fileError(ErrorCode::ParseError, name_, line_, "%s", msg);
	}
	Status endOfFile() const;

	Status declaration();
	Status comment();
	Status readName(std::string &out);
	Status attributeValue(std::string &out);
	Status startTag(std::vector<XmlElement> &out, int parent, bool &selfClosing);
	Status endTag(const XmlElement &open);
	Status content(std::vector<XmlElement> &out, int current);

	std::string_view text_;
	const char *name_;
	size_t pos_ = 0;
	int line_ = 1;
	std::vector<int> open_; // indices of elements not yet closed
	const std::vector<XmlElement> *elements_ = nullptr;
};

Status Parser::endOfFile() const
{
	if (open_.empty())
		return fileError(ErrorCode::ParseError, name_, line_,
				 "unexpected end of file (truncated?)");
	const XmlElement &e = (*elements_)[open_.back()];
	return fileError(ErrorCode::ParseError, name_, line_,
			 "unexpected end of file: <%s> opened on line %d is not closed "
			 "(truncated?)",
			 e.name.c_str(), e.line);
}

Status Parser::declaration()
{
	// "<?xml" then attributes up to "?>"; only version/encoding/standalone are checked
	// for syntax, their values are not interpreted (the files are ASCII).
	advance(5);
	while (true) {
		skipSpace();
		if (atEnd())
			return endOfFile();
		if (lookingAt("?>")) {
			advance(2);
			return Status::success();
		}
		std::string attr, value;
		Status st = readName(attr);
		if (!st.ok())
			return st;
		if (attr != "version" && attr != "encoding" && attr != "standalone")
			return error("unknown attribute '%s' in the XML declaration", attr.c_str());
		skipSpace();
		if (peek() != '=')
			return error("expected '=' after '%s' in the XML declaration", attr.c_str());
		advance();
		skipSpace();
		st = attributeValue(value);
		if (!st.ok())
			return st;
	}
}

Status Parser::comment()
{
	advance(4);
	size_t end = text_.find("-->", pos_);
	if (end == std::string_view::npos)
		return fileError(ErrorCode::ParseError, name_, line_,
				 "comment is not closed with '-->' (truncated?)");
	advance(end + 3 - pos_);
	return Status::success();
}

Status Parser::readName(std::string &out)
{
	if (atEnd())
		return endOfFile();
	if (!isNameStart(peek())) {
		char c[2];
		return error("expected a name, found '%s'", quote(text_.substr(pos_, 1), c, sizeof(c)));
	}
	size_t start = pos_;
	while (!atEnd() && isNameChar(peek()))
		advance();
	out.assign(text_.substr(start, pos_ - start));
	return Status::success();
}

Status Parser::attributeValue(std::string &out)
{
	const char q = peek();
	if (q != '"' && q != '\'')
		return atEnd() ? endOfFile() : error("attribute value must be quoted");
	advance();
	out.clear();
	while (true) {
		if (atEnd())
			return fileError(ErrorCode::ParseError, name_, line_,
					 "attribute value is not closed (truncated?)");
		const char c = peek();
		if (c == q) {
			advance();
			return Status::success();
		}
		if (c == '<')
			return error("'<' inside an attribute value");
		if (c != '&') {
			out += c;
			advance();
			continue;
		}
		size_t semi = text_.find(';', pos_);
		if (semi == std::string_view::npos || semi - pos_ > 10)
			return error("'&' does not start an entity (write &amp;)");
		const std::string_view ent = text_.substr(pos_ + 1, semi - pos_ - 1);
		char q[16];
		if (ent == "lt") {
			out += '<';
		} else if (ent == "gt") {
			out += '>';
		} else if (ent == "amp") {
			out += '&';
		} else if (ent == "quot") {
			out += '"';
		} else if (ent == "apos") {
			out += '\'';
		} else if (ent.size() > 1 && ent[0] == '#') {
			const bool hex = ent[1] == 'x';
			unsigned long cp = 0;
			const std::string_view digits = ent.substr(hex ? 2 : 1);
			bool okDigits = !digits.empty();
			for (char d : digits) {
				int v = -1;
				if (d >= '0' && d <= '9')
					v = d - '0';
				else if (hex && d >= 'a' && d <= 'f')
					v = d - 'a' + 10;
				else if (hex && d >= 'A' && d <= 'F')
					v = d - 'A' + 10;
				if (v < 0) {
					okDigits = false;
					break;
				}
				cp = cp * (hex ? 16 : 10) + static_cast<unsigned long>(v);
			}
			if (!okDigits || cp == 0 || cp > 0x10ffff)
				return error("bad character reference '&%s;'",
					     quote(ent, q, sizeof(q)));
			appendUtf8(out, cp);
		} else {
			return error("unknown entity '&%s;'", quote(ent, q, sizeof(q)));
		}
		advance(semi + 1 - pos_);
	}
}

Status Parser::startTag(std::vector<XmlElement> &out, int parent, bool &selfClosing)
{
	advance(); // '<'
	XmlElement e;
	e.line = line_;
	e.parent = parent;
	e.depth = parent < 0 ? 0 : out[parent].depth + 1;
	Status st = readName(e.name);
	if (!st.ok())
		return st;
	std::unordered_set<std::string_view> seen;
	while (true) {
		const bool spaced = isSpace(peek());
		skipSpace();
		if (atEnd())
			return fileError(ErrorCode::ParseError, name_, line_,
					 "unexpected end of file inside the tag <%s> (truncated?)",
					 e.name.c_str());
		if (peek() == '>' || lookingAt("/>")) {
			selfClosing = peek() == '/';
			advance(selfClosing ? 2 : 1);
			break;
		}
		if (!spaced)
			return error("expected whitespace, '>' or '/>' in <%s>", e.name.c_str());
		XmlAttribute a;
		a.line = line_;
		const size_t nameStart = pos_;
		st = readName(a.name);
		if (!st.ok())
			return st;
		// A set of the names (views into the text): scanning the attributes so far for
		// each new one made a tag of 100k attributes take 34 s.
		if (!seen.insert(text_.substr(nameStart, a.name.size())).second)
			return error("duplicate attribute '%s'", a.name.c_str());
		skipSpace();
		if (peek() != '=')
			return atEnd() ? endOfFile()
				       : error("expected '=' after attribute '%s'", a.name.c_str());
		advance();
		skipSpace();
		st = attributeValue(a.value);
		if (!st.ok())
			return st;
		e.attributes.push_back(std::move(a));
	}
	out.push_back(std::move(e));
	return Status::success();
}

Status Parser::endTag(const XmlElement &open)
{
	const int line = line_;
	advance(2); // "</"
	std::string closeName;
	Status st = readName(closeName);
	if (!st.ok())
		return st;
	skipSpace();
	if (atEnd())
		return endOfFile();
	if (peek() != '>')
		return error("expected '>' to end </%s>", closeName.c_str());
	advance();
	if (closeName != open.name)
		return fileError(ErrorCode::ParseError, name_, line,
				 "</%s> does not match <%s> opened on line %d", closeName.c_str(),
				 open.name.c_str(), open.line);
	return Status::success();
}

// Children of element `current` (or the document when -1) up to its end tag.
Status Parser::content(std::vector<XmlElement> &out, int current)
{
	bool rootSeen = false;
	while (true) {
		skipSpace();
		if (atEnd()) {
			if (current >= 0)
				return endOfFile();
			if (!rootSeen)
				return fileError(ErrorCode::ParseError, name_, line_,
						 "no root element");
			return Status::success();
		}
		if (peek() != '<') {
			size_t end = text_.find('<', pos_);
			char q[40];
			quote(trim(text_.substr(pos_, end == std::string_view::npos
							      ? std::string_view::npos
							      : end - pos_)),
			      q, sizeof(q));
			return error("unexpected text '%s' (only elements and attributes are read)", q);
		}
		if (lookingAt("<!--")) {
			Status st = comment();
			if (!st.ok())
				return st;
			continue;
		}
		if (lookingAt("<?xml") && (isSpace(peek(5)) || peek(5) == '?'))
			return error("the XML declaration must come first in the file");
		if (lookingAt("<?"))
			return error("processing instructions are not supported");
		if (lookingAt("<![CDATA["))
			return error("CDATA sections are not supported");
		if (lookingAt("<!"))
			return error("DOCTYPE and other declarations are not supported");
		if (lookingAt("</")) {
			if (current < 0)
				return error("closing tag without an open element");
			return endTag(out[current]);
		}
		if (current < 0 && rootSeen)
			return error("content after the root element");
		bool selfClosing = false;
		const int index = static_cast<int>(out.size());
		Status st = startTag(out, current, selfClosing);
		if (!st.ok())
			return st;
		rootSeen = true;
		if (!selfClosing) {
			if (open_.size() >= 64)
				return error("elements nested too deeply");
			open_.push_back(index);
			st = content(out, index);
			if (!st.ok())
				return st;
			open_.pop_back();
		}
	}
}

Status Parser::run(std::vector<XmlElement> &out)
{
	out.clear();
	elements_ = &out;
	if (lookingAt("\xef\xbb\xbf"))
		pos_ += 3;
	if (lookingAt("<?xml") && (isSpace(peek(5)) || peek(5) == '?')) {
		Status st = declaration();
		if (!st.ok())
			return st;
	}
	return content(out, -1);
}

} // namespace

Status parseXml(const char *data, size_t size, const char *name, std::vector<XmlElement> &out)
{
	try {
		Parser parser(data, size, name);
		return parser.run(out);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: out of memory reading XML", name);
	}
}

} // namespace calped::calib
