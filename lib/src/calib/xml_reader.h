// SPDX-License-Identifier: BSD-2-Clause
// A strict reader for the XML subset calibration and annotation files use: an optional XML
// declaration, comments, elements with attributes, self-closing tags and whitespace between
// them. No text content, CDATA, DOCTYPE or processing instructions; the five predefined
// entities and character references in attribute values. Errors name the line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <calped/status.h>

namespace calped::calib {

struct XmlAttribute {
	std::string name;
	std::string value;
	int line = 0;
};

struct XmlElement {
	std::string name;
	int line = 0;
	int parent = -1; // index in the element list, -1 for the root
	int depth = 0;	 // 0 for the root
	std::vector<XmlAttribute> attributes;

	const XmlAttribute *attribute(std::string_view attrName) const;
};

// Parses the whole document; elements come in document order (the root first).
// ParseError naming `name` and the line for any malformed or unsupported construct,
// OutOfMemory if the element list cannot grow.
Status parseXml(const char *data, size_t size, const char *name, std::vector<XmlElement> &out);

} // namespace calped::calib
