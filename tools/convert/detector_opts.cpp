// SPDX-License-Identifier: BSD-2-Clause
#include "detector_opts.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace calped {
namespace convert {

namespace {

std::string lower(std::string s)
{
	for (char &c : s)
		c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return s;
}

// Exactly `count` numbers (one-element fields may also be given as a vector of one).
Status readValues(const MatNode &parent, const char *name, size_t count, std::vector<double> &v)
{
	MatNode node;
	Status s = field(parent, name, node);
	if (s.ok())
		s = numbers(node, v);
	if (s.ok() && v.size() != count)
		return Status::error(ErrorCode::ModelInvalid, "%s is %s, expected %zu number%s",
				     node.path.c_str(), shapeString(node).c_str(), count,
				     count == 1 ? "" : "s");
	for (size_t i = 0; s.ok() && i < v.size(); i++)
		if (!std::isfinite(v[i]))
			return Status::error(ErrorCode::ModelInvalid, "%s(%zu) = %g is not finite",
					     node.path.c_str(), i + 1, v[i]);
	return s;
}

Status toInt(const std::string &path, double v, int32_t &out)
{
	if (v != std::floor(v) || v < std::numeric_limits<int32_t>::min() ||
	    v > std::numeric_limits<int32_t>::max())
		return Status::error(ErrorCode::ModelInvalid, "%s = %.17g is not a 32-bit integer",
				     path.c_str(), v);
	out = static_cast<int32_t>(v);
	return Status::success();
}

Status toFloat(const std::string &path, double v, float &out)
{
	if (std::fabs(v) > std::numeric_limits<float>::max())
		return Status::error(ErrorCode::ModelInvalid, "%s = %g does not fit a float",
				     path.c_str(), v);
	out = static_cast<float>(v); // nearest float; the blob stores f32
	return Status::success();
}

Status readInt(const MatNode &parent, const char *name, int32_t &out)
{
	std::vector<double> v;
	Status s = readValues(parent, name, 1, v);
	return s.ok() ? toInt(parent.path + "." + name, v[0], out) : s;
}

Status readFloat(const MatNode &parent, const char *name, float &out)
{
	std::vector<double> v;
	Status s = readValues(parent, name, 1, v);
	return s.ok() ? toFloat(parent.path + "." + name, v[0], out) : s;
}

Status readIntPair(const MatNode &parent, const char *name, int32_t &first, int32_t &second)
{
	std::vector<double> v;
	Status s = readValues(parent, name, 2, v);
	const std::string path = parent.path + "." + name;
	if (s.ok())
		s = toInt(path, v[0], first);
	return s.ok() ? toInt(path, v[1], second) : s;
}

Status readFloats(const MatNode &parent, const char *name, size_t count, float *out)
{
	std::vector<double> v;
	Status s = readValues(parent, name, count, v);
	for (size_t i = 0; s.ok() && i < count; i++)
		s = toFloat(parent.path + "." + name, v[i], out[i]);
	return s;
}

Status readText(const MatNode &parent, const char *name, std::string &out)
{
	MatNode node;
	Status s = field(parent, name, node);
	return s.ok() ? text(node, out) : s;
}

// A channel type the toolbox can switch off; calped always computes all ten channels.
Status requireEnabled(const MatNode &channel)
{
	if (!hasField(channel, "enabled"))
		return Status::success();
	int32_t enabled = 1;
	Status s = readInt(channel, "enabled", enabled);
	if (s.ok() && enabled == 0)
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s.enabled = 0: calped needs all ten ACF channels",
				     channel.path.c_str());
	return s;
}

// The toolbox only tests softBin's sign and parity; store one representative per behaviour.
int32_t canonicalSoftBin(int32_t v)
{
	const bool odd = v % 2 != 0;
	if (v < 0)
		return odd ? -1 : -2;
	return odd ? 1 : 0;
}

Status readColor(const MatNode &pChns, ModelParams &p)
{
	MatNode pColor;
	Status s = field(pChns, "pColor", pColor);
	if (s.ok())
		s = requireEnabled(pColor);
	if (s.ok())
		s = readInt(pColor, "smooth", p.colorSmooth);
	std::string space;
	if (s.ok())
		s = readText(pColor, "colorSpace", space);
	if (s.ok() && lower(space) != "luv")
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s.colorSpace = '%s' is not supported (only 'luv')",
				     pColor.path.c_str(), space.c_str());
	return s;
}

Status readGradMag(const MatNode &pChns, ModelParams &p)
{
	MatNode pGradMag;
	Status s = field(pChns, "pGradMag", pGradMag);
	if (s.ok())
		s = requireEnabled(pGradMag);
	if (s.ok())
		s = readInt(pGradMag, "colorChn", p.gradColorChn);
	if (s.ok())
		s = readInt(pGradMag, "normRad", p.gradNormRad);
	if (s.ok())
		s = readFloat(pGradMag, "normConst", p.gradNormConst);
	if (s.ok())
		s = readInt(pGradMag, "full", p.gradFull);
	return s;
}

Status readGradHist(const MatNode &pChns, ModelParams &p)
{
	MatNode pGradHist;
	Status s = field(pChns, "pGradHist", pGradHist);
	if (s.ok())
		s = requireEnabled(pGradHist);
	if (!s.ok())
		return s;
	// An empty binSize means "same as shrink".
	MatNode binSize;
	s = field(pGradHist, "binSize", binSize);
	if (s.ok() && elementCount(binSize) == 0)
		p.histBinSize = p.shrink;
	else if (s.ok())
		s = readInt(pGradHist, "binSize", p.histBinSize);
	if (s.ok())
		s = readInt(pGradHist, "nOrients", p.nOrients);
	int32_t softBin = 0;
	if (s.ok())
		s = readInt(pGradHist, "softBin", softBin);
	p.softBin = canonicalSoftBin(softBin);
	int32_t useHog = 0;
	if (s.ok() && hasField(pGradHist, "useHog"))
		s = readInt(pGradHist, "useHog", useHog);
	if (s.ok() && useHog != 0)
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s.useHog = %d: HOG/FHOG channels are not supported",
				     pGradHist.path.c_str(), useHog);
	return s;
}

Status readChannels(const MatNode &pPyramid, ModelParams &p)
{
	MatNode pChns;
	Status s = field(pPyramid, "pChns", pChns);
	if (s.ok())
		s = readInt(pChns, "shrink", p.shrink);
	if (s.ok() && hasField(pChns, "pCustom")) {
		MatNode pCustom;
		s = field(pChns, "pCustom", pCustom);
		if (s.ok() && elementCount(pCustom) != 0)
			return Status::error(ErrorCode::ModelUnsupported,
					     "%s is %s: custom channels are not supported",
					     pCustom.path.c_str(), shapeString(pCustom).c_str());
	}
	if (s.ok())
		s = readColor(pChns, p);
	if (s.ok())
		s = readGradMag(pChns, p);
	if (s.ok())
		s = readGradHist(pChns, p);
	return s;
}

Status readPyramid(const MatNode &opts, ModelParams &p)
{
	MatNode pPyramid;
	Status s = field(opts, "pPyramid", pPyramid);
	if (s.ok())
		s = readChannels(pPyramid, p);
	if (s.ok())
		s = readInt(pPyramid, "nPerOct", p.nPerOct);
	if (s.ok())
		s = readInt(pPyramid, "nOctUp", p.nOctUp);
	if (s.ok())
		s = readInt(pPyramid, "nApprox", p.nApprox);
	if (s.ok())
		s = readFloats(pPyramid, "lambdas", 3, p.lambdas);
	if (s.ok())
		s = readIntPair(pPyramid, "pad", p.padH, p.padW);
	float minDs[2] = { 0, 0 };
	if (s.ok())
		s = readFloats(pPyramid, "minDs", 2, minDs);
	p.minDsH = minDs[0];
	p.minDsW = minDs[1];
	if (s.ok())
		s = readInt(pPyramid, "smooth", p.pyramidSmooth);
	return s;
}

Status readNms(const MatNode &opts, ModelParams &p)
{
	MatNode pNms;
	Status s = field(opts, "pNms", pNms);
	std::string type;
	if (s.ok())
		s = readText(pNms, "type", type);
	if (s.ok() && lower(type) != "maxg")
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s.type = '%s' is not supported (only 'maxg')", pNms.path.c_str(),
				     type.c_str());
	if (s.ok())
		s = readFloat(pNms, "overlap", p.nmsOverlap);
	// bbNms defaults to 'union' when ovrDnm is absent.
	std::string dnm = "union";
	if (s.ok() && hasField(pNms, "ovrDnm"))
		s = readText(pNms, "ovrDnm", dnm);
	if (!s.ok())
		return s;
	if (lower(dnm) == "min")
		p.nmsOverlapDenominator = NmsOverlapDenominator::Min;
	else if (lower(dnm) == "union")
		p.nmsOverlapDenominator = NmsOverlapDenominator::Union;
	else
		return Status::error(ErrorCode::ModelUnsupported,
				     "%s.ovrDnm = '%s' is not supported ('min' or 'union')",
				     pNms.path.c_str(), dnm.c_str());
	return s;
}

} // namespace

Status readDetectorOpts(const MatNode &opts, ModelParams &out)
{
	ModelParams p;
	// LDCF's filters are read by readDetectorFilters (detector_filters.h).
	Status s = readPyramid(opts, p);
	float modelDs[2] = { 0, 0 };
	if (s.ok())
		s = readFloats(opts, "modelDs", 2, modelDs);
	p.modelDsH = modelDs[0];
	p.modelDsW = modelDs[1];
	if (s.ok())
		s = readIntPair(opts, "modelDsPad", p.modelDsPadH, p.modelDsPadW);
	if (s.ok())
		s = readInt(opts, "stride", p.stride);
	if (s.ok())
		s = readFloat(opts, "cascThr", p.cascThr);
	if (s.ok())
		s = readNms(opts, p);
	if (s.ok())
		out = p;
	return s;
}

} // namespace convert
} // namespace calped
