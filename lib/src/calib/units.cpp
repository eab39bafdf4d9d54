// SPDX-License-Identifier: BSD-2-Clause
#include <calped/calibration.h>

#include <string_view>

namespace calped {

const char *lengthUnitName(LengthUnit unit)
{
	switch (unit) {
	case LengthUnit::Millimetre: return "mm";
	case LengthUnit::Centimetre: return "cm";
	case LengthUnit::Metre: return "m";
	}
	return "?";
}

double metresPerUnit(LengthUnit unit)
{
	switch (unit) {
	case LengthUnit::Millimetre: return 0.001;
	case LengthUnit::Centimetre: return 0.01;
	case LengthUnit::Metre: return 1.0;
	}
	return 1.0;
}

bool parseLengthUnit(const char *text, size_t length, LengthUnit &out)
{
	const std::string_view s(text, length);
	if (s == "mm")
		out = LengthUnit::Millimetre;
	else if (s == "cm")
		out = LengthUnit::Centimetre;
	else if (s == "m")
		out = LengthUnit::Metre;
	else
		return false;
	return true;
}

} // namespace calped
