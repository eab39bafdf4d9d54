// SPDX-License-Identifier: BSD-2-Clause
// CVML ground truth through expat. Structure errors (a box outside an object, a frame
// without a number, a size that is not a positive number...) stop the parse and name the
// line, as XML syntax errors do.
#include "ground_truth.h"

#if CALPED_EVAL_HAVE_EXPAT

#include <cstdint>
#include <cstring>
#include <map>

#include <expat.h>

#include "text_fields.h"

namespace calped::eval_tool {

namespace {

struct CvmlState {
	XML_Parser parser = nullptr;
	std::string path;
	GroundTruth *gt = nullptr;
	std::string error;
	long frame = -1;            // 0-based frame being read, -1 outside <frame>
	bool inObject = false;
	bool objectHasBox = false;
	long objectLine = 0;
	long frames = 0;
	std::map<long, long> frameLines; // frame number -> line, to report duplicates

	long line() const { return static_cast<long>(XML_GetCurrentLineNumber(parser)); }

	void fail(const std::string &message)
	{
		if (error.empty())
			error = lineError(path, line(), message);
		XML_StopParser(parser, XML_FALSE);
	}
};

const char *attribute(const XML_Char **attrs, const char *name)
{
	for (int i = 0; attrs[i]; i += 2)
		if (std::strcmp(attrs[i], name) == 0)
			return attrs[i + 1];
	return nullptr;
}

bool numberAttribute(CvmlState &s, const XML_Char **attrs, const char *element,
		     const char *name, double &out)
{
	const char *v = attribute(attrs, name);
	if (!v) {
		s.fail(std::string("<") + element + "> lacks attribute \"" + name + "\"");
		return false;
	}
	if (!parseDouble(v, out)) {
		s.fail(std::string("<") + element + "> attribute " + name + "=\"" + printable(v) +
		       "\" is not a number");
		return false;
	}
	return true;
}

void XMLCALL onStart(void *user, const XML_Char *name, const XML_Char **attrs)
{
	CvmlState &s = *static_cast<CvmlState *>(user);
	if (!s.error.empty())
		return;
	if (std::strcmp(name, "frame") == 0) {
		if (s.frame >= 0)
			return s.fail("<frame> inside another <frame>");
		double number;
		if (!numberAttribute(s, attrs, "frame", "number", number))
			return;
		long k;
		if (!parseLong(attribute(attrs, "number"), k) || k < 0)
			return s.fail(std::string("<frame> number=\"") +
				      printable(attribute(attrs, "number")) +
				      "\" is not a whole number >= 0");
		auto seen = s.frameLines.find(k);
		if (seen != s.frameLines.end())
			return s.fail("frame " + std::to_string(k) + " appears twice (first at line " +
				      std::to_string(seen->second) + ")");
		s.frameLines[k] = s.line();
		s.frame = k;
		s.frames++;
	} else if (std::strcmp(name, "object") == 0) {
		if (s.frame < 0)
			return s.fail("<object> outside a <frame>");
		if (s.inObject)
			return s.fail("<object> inside another <object>");
		s.inObject = true;
		s.objectHasBox = false;
		s.objectLine = s.line();
	} else if (std::strcmp(name, "box") == 0) {
		if (!s.inObject)
			return s.fail("<box> outside an <object>");
		if (s.objectHasBox)
			return s.fail("second <box> in one <object>");
		double h, w, xc, yc;
		if (!numberAttribute(s, attrs, "box", "h", h) ||
		    !numberAttribute(s, attrs, "box", "w", w) ||
		    !numberAttribute(s, attrs, "box", "xc", xc) ||
		    !numberAttribute(s, attrs, "box", "yc", yc))
			return;
		if (!(w > 0 && h > 0))
			return s.fail("<box> has a size that is not positive (w=" + std::to_string(w) +
				      ", h=" + std::to_string(h) + ")");
		GtBox b;
		b.box = Box{ xc - w / 2, yc - h / 2, w, h };
		// CVML numbers frames from 0; the harness numbers images from 1.
		s.gt->add(s.frame + 1, b);
		s.objectHasBox = true;
	}
}

void XMLCALL onEnd(void *user, const XML_Char *name)
{
	CvmlState &s = *static_cast<CvmlState *>(user);
	if (!s.error.empty())
		return;
	if (std::strcmp(name, "frame") == 0) {
		s.frame = -1;
	} else if (std::strcmp(name, "object") == 0) {
		s.inObject = false;
		if (!s.objectHasBox)
			s.fail("<object> (opened at line " + std::to_string(s.objectLine) +
			       ") has no <box>");
	}
}

} // namespace

bool cvmlSupported()
{
	return true;
}

bool readCvmlGroundTruth(const std::string &path, GroundTruth &out, std::string &error)
{
	out = GroundTruth();
	std::string text;
	if (!readTextFile(path, text, error)) {
		error = "ground truth: " + error;
		return false;
	}
	return parseCvmlGroundTruth(text.data(), text.size(), path, out, error);
}

bool parseCvmlGroundTruth(const char *data, size_t size, const std::string &path,
			  GroundTruth &out, std::string &error)
{
	out = GroundTruth();
	if (size > static_cast<size_t>(INT32_MAX)) {
		error = "ground truth " + path + ": file too large";
		return false;
	}
	CvmlState s;
	s.parser = XML_ParserCreate(nullptr);
	if (!s.parser) {
		error = "ground truth " + path + ": cannot create the XML parser";
		return false;
	}
	s.path = path;
	s.gt = &out;
	XML_SetUserData(s.parser, &s);
	XML_SetElementHandler(s.parser, onStart, onEnd);
	const bool parsed = XML_Parse(s.parser, data, static_cast<int>(size), XML_TRUE) ==
			    XML_STATUS_OK;
	if (!parsed && s.error.empty())
		s.error = lineError(path, static_cast<long>(XML_GetCurrentLineNumber(s.parser)),
				    std::string("malformed XML: ") +
					    XML_ErrorString(XML_GetErrorCode(s.parser)));
	XML_ParserFree(s.parser);
	if (s.error.empty() && s.frames == 0)
		s.error = path + ": no <frame> elements: not CVML ground truth";
	if (!s.error.empty()) {
		error = s.error;
		out = GroundTruth();
		return false;
	}
	return true;
}

} // namespace calped::eval_tool

#else // no expat

namespace calped::eval_tool {

bool cvmlSupported()
{
	return false;
}

bool parseCvmlGroundTruth(const char *, size_t, const std::string &path, GroundTruth &out,
			  std::string &error)
{
	out = GroundTruth();
	error = "ground truth " + path + " is CVML XML, but calped-eval was built without expat " +
		"(install libexpat1-dev and reconfigure the build)";
	return false;
}

bool readCvmlGroundTruth(const std::string &path, GroundTruth &out, std::string &error)
{
	return parseCvmlGroundTruth(nullptr, 0, path, out, error);
}

} // namespace calped::eval_tool

#endif
