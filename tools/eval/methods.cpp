// SPDX-License-Identifier: BSD-2-Clause
#include "methods.h"


namespace calped::eval_tool {

namespace {

// Both modes are calped::Detector; they differ in the configuration.
class DetectorMethod : public Method
{
public:
	Status detect(const ImageView &image, Detections &out) override
	{
		return detector_->detect(image, out);
	}
	const FrameStats &lastStats() const override { return detector_->lastStats(); }

protected:
	bool setUp(const MethodSetup &setup, const apps::DetectorOptions &options,
		   const CameraModel *camera, std::string &error)
	{
		return apps::createDetector(*setup.model, options, setup.maxWidth, setup.maxHeight,
					    camera, detector_, error);
	}

	std::unique_ptr<Detector> detector_;
};

// Dollár's sliding window over the whole fast feature pyramid.
class GenericMethod : public DetectorMethod
{
public:
	static bool create(const MethodSetup &setup, std::unique_ptr<Method> &out,
			   std::string &error)
	{
		std::unique_ptr<GenericMethod> m(new GenericMethod);
		apps::DetectorOptions options = setup.options;
		options.method = apps::MethodChoice::Generic;
		if (!m->setUp(setup, options, nullptr, error))
			return false;
		out = std::move(m);
		return true;
	}
};

// The thesis's method: only the pyramid levels and windows where a person of plausible
// world height can stand, given the camera's calibration (--calib, any format the core
// reads), with the detector's default height range.
class CalibratedMethod : public DetectorMethod
{
public:
	static bool create(const MethodSetup &setup, std::unique_ptr<Method> &out,
			   std::string &error)
	{
		return createWith(setup, false, out, error);
	}
	// The same with static-scene rejection (DetectorConfig::staticRejection, defaults).
	static bool createStatic(const MethodSetup &setup, std::unique_ptr<Method> &out,
				 std::string &error)
	{
		return createWith(setup, true, out, error);
	}

private:
	static bool createWith(const MethodSetup &setup, bool rejectStatic,
			       std::unique_ptr<Method> &out, std::string &error)
	{
		std::unique_ptr<CalibratedMethod> m(new CalibratedMethod);
		if (!apps::loadCalibrationFile(setup.options.calibPath, m->camera_, error))
			return false;
		apps::DetectorOptions options = setup.options;
		options.method = apps::MethodChoice::Calibrated;
		options.rejectStatic = rejectStatic;
		if (!m->setUp(setup, options, &m->camera_, error))
			return false;
		out = std::move(m);
		return true;
	}

	CameraModel camera_;
};

} // namespace

const std::vector<MethodEntry> &methodRegistry()
{
	static const std::vector<MethodEntry> kMethods = {
		{ "generic", false, &GenericMethod::create },
		{ "calibrated", true, &CalibratedMethod::create },
		{ "calibrated-static", true, &CalibratedMethod::createStatic },
	};
	return kMethods;
}

const MethodEntry *findMethod(const std::string &name)
{
	for (const MethodEntry &m : methodRegistry())
		if (name == m.name)
			return &m;
	return nullptr;
}

std::string methodNames()
{
	std::string names;
	for (const MethodEntry &m : methodRegistry())
		names += (names.empty() ? "" : ", ") + std::string(m.name);
	return names;
}

} // namespace calped::eval_tool
