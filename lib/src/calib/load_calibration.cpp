// SPDX-License-Identifier: BSD-2-Clause
// Picks the calibration format from the content (file names are not trusted).
#include <calped/calibration.h>

#include <cctype>
#include <string_view>

#include "calib/text_util.h"

namespace calped {

const char *calibrationFormatName(CalibrationFormat format)
{
	switch (format) {
	case CalibrationFormat::Unknown: return "unknown";
	case CalibrationFormat::TsaiXml: return "Tsai XML";
	case CalibrationFormat::TownCentreCi: return "Town Centre .ci";
	case CalibrationFormat::ProjectionText: return "projection matrix text";
	case CalibrationFormat::OpenCvYaml: return "OpenCV YAML";
	}
	return "unknown";
}

CalibrationFormat detectCalibrationFormat(const char *data, size_t size)
{
	std::string_view text(data, size);
	if (calib::startsWith(text, "\xef\xbb\xbf"))
		text.remove_prefix(3);
	calib::LineReader lines(text.data(), text.size());
	std::string_view line;
	while (lines.next(line)) {
		const std::string_view t = calib::trim(line);
		if (t.empty())
			continue;
		if (calib::startsWith(t, "%YAML"))
			return CalibrationFormat::OpenCvYaml;
		if (t[0] == '<')
			return CalibrationFormat::TsaiXml;
		if (t[0] == '#')
			continue;
		// "Identifier = value" is the Town Centre layout; anything else is read as P.
		size_t i = 0;
		while (i < t.size() && (std::isalnum(static_cast<unsigned char>(t[i])) || t[i] == '_'))
			i++;
		if (i > 0 && std::isalpha(static_cast<unsigned char>(t[0])) &&
		    calib::startsWith(calib::trim(t.substr(i)), "="))
			return CalibrationFormat::TownCentreCi;
		return CalibrationFormat::ProjectionText;
	}
	return CalibrationFormat::Unknown;
}

Status loadCalibration(const char *data, size_t size, const char *name, CameraModel &out)
{
	switch (detectCalibrationFormat(data, size)) {
	case CalibrationFormat::TsaiXml: return loadTsaiXml(data, size, name, out);
	case CalibrationFormat::TownCentreCi: return loadTownCentreCi(data, size, name, out);
	case CalibrationFormat::ProjectionText: return loadProjectionText(data, size, name, out);
	case CalibrationFormat::OpenCvYaml: return loadOpenCvYaml(data, size, name, out);
	case CalibrationFormat::Unknown: break;
	}
	return calib::fileError(ErrorCode::ParseError, name, 0,
				"empty calibration file (no content besides comments)");
}

} // namespace calped
