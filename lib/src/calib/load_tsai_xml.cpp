// SPDX-License-Identifier: BSD-2-Clause
// Tsai calibration XML as PETS 2009 ships it: <Camera> with <Geometry>, <Intrinsic> and
// <Extrinsic> elements whose attributes hold the parameters (world unit: millimetres).
#include <calped/calibration.h>

#include <cstdio>
#include <new>
#include <vector>

#include "calib/text_util.h"
#include "calib/xml_reader.h"

namespace calped {

namespace {

struct Field {
	const char *attr;
	double TsaiCamera::*member;
	bool positive;
};

const Field kGeometry[] = {
	{ "width", &TsaiCamera::width, true }, { "height", &TsaiCamera::height, true },
	{ "ncx", &TsaiCamera::ncx, true },     { "nfx", &TsaiCamera::nfx, true },
	{ "dx", &TsaiCamera::dx, true },       { "dy", &TsaiCamera::dy, true },
	{ "dpx", &TsaiCamera::dpx, true },     { "dpy", &TsaiCamera::dpy, true },
};
const Field kIntrinsic[] = {
	{ "focal", &TsaiCamera::focal, true }, { "kappa1", &TsaiCamera::kappa1, false },
	{ "cx", &TsaiCamera::cx, false },      { "cy", &TsaiCamera::cy, false },
	{ "sx", &TsaiCamera::sx, true },
};
const Field kExtrinsic[] = {
	{ "tx", &TsaiCamera::tx, false }, { "ty", &TsaiCamera::ty, false },
	{ "tz", &TsaiCamera::tz, false }, { "rx", &TsaiCamera::rx, false },
	{ "ry", &TsaiCamera::ry, false }, { "rz", &TsaiCamera::rz, false },
};

struct Section {
	const char *element;
	const Field *fields;
	size_t count;
};

const Section kSections[] = {
	{ "Geometry", kGeometry, sizeof(kGeometry) / sizeof(Field) },
	{ "Intrinsic", kIntrinsic, sizeof(kIntrinsic) / sizeof(Field) },
	{ "Extrinsic", kExtrinsic, sizeof(kExtrinsic) / sizeof(Field) },
};

Status readSection(const calib::XmlElement &e, const Section &section, const char *name,
		   TsaiCamera &out)
{
	using calib::fileError;
	for (const calib::XmlAttribute &a : e.attributes) {
		bool known = false;
		for (size_t i = 0; i < section.count; i++)
			known = known || a.name == section.fields[i].attr;
		if (!known)
			return fileError(ErrorCode::ParseError, name, a.line,
					 "unknown attribute '%s' in <%s>", a.name.c_str(),
					 section.element);
	}
	for (size_t i = 0; i < section.count; i++) {
		const Field &f = section.fields[i];
		const calib::XmlAttribute *a = e.attribute(f.attr);
		if (!a)
			return fileError(ErrorCode::ParseError, name, e.line,
					 "<%s> lacks attribute '%s'", section.element, f.attr);
		double v = 0;
		calib::NumberResult r = calib::parseNumber(calib::trim(a->value), v);
		if (r != calib::NumberResult::Ok) {
			char field[48];
			std::snprintf(field, sizeof(field), "<%s> %s", section.element, f.attr);
			return calib::numberError(r, name, a->line, field, a->value);
		}
		if (f.positive && !(v > 0.0))
			return fileError(ErrorCode::InvalidArgument, name, a->line,
					 "<%s> %s = %g must be > 0", section.element, f.attr, v);
		out.*f.member = v;
	}
	return Status::success();
}

Status parseElements(const std::vector<calib::XmlElement> &elements, const char *name,
		     TsaiCamera &out)
{
	using calib::fileError;
	const calib::XmlElement &root = elements.front();
	if (root.name != "Camera")
		return fileError(ErrorCode::ParseError, name, root.line,
				 "root element is <%s>, expected <Camera>", root.name.c_str());
	for (const calib::XmlAttribute &a : root.attributes)
		if (a.name != "name")
			return fileError(ErrorCode::ParseError, name, a.line,
					 "unknown attribute '%s' in <Camera>", a.name.c_str());

	const size_t nSections = sizeof(kSections) / sizeof(kSections[0]);
	int seenLine[nSections] = {};
	TsaiCamera cam;
	for (size_t i = 1; i < elements.size(); i++) {
		const calib::XmlElement &e = elements[i];
		if (e.depth > 1) {
			const calib::XmlElement &parent = elements[e.parent];
			return fileError(ErrorCode::ParseError, name, e.line,
					 "<%s> may not contain elements (found <%s>)",
					 parent.name.c_str(), e.name.c_str());
		}
		size_t s = 0;
		while (s < nSections && e.name != kSections[s].element)
			s++;
		if (s == nSections)
			return fileError(ErrorCode::ParseError, name, e.line,
					 "unknown element <%s> in <Camera>", e.name.c_str());
		if (seenLine[s])
			return fileError(ErrorCode::ParseError, name, e.line,
					 "second <%s> element (the first is on line %d)",
					 e.name.c_str(), seenLine[s]);
		seenLine[s] = e.line;
		Status st = readSection(e, kSections[s], name, cam);
		if (!st.ok())
			return st;
	}
	for (size_t s = 0; s < nSections; s++)
		if (!seenLine[s])
			return fileError(ErrorCode::ParseError, name, 0,
					 "<Camera> has no <%s> element", kSections[s].element);
	out = cam;
	return Status::success();
}

} // namespace

Status parseTsaiXml(const char *data, size_t size, const char *name, TsaiCamera &out)
{
	std::vector<calib::XmlElement> elements;
	Status st = calib::parseXml(data, size, name, elements);
	if (!st.ok())
		return st;
	try {
		return parseElements(elements, name, out);
	} catch (const std::bad_alloc &) {
		return Status::error(ErrorCode::OutOfMemory, "%s: out of memory", name);
	}
}

Status loadTsaiXml(const char *data, size_t size, const char *name, CameraModel &out)
{
	TsaiCamera cam;
	Status st = parseTsaiXml(data, size, name, cam);
	if (!st.ok())
		return st;
	return calib::withFileName(CameraModel::fromTsai(cam, LengthUnit::Millimetre, out), name);
}

} // namespace calped
