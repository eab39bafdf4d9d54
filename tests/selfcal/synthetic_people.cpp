// SPDX-License-Identifier: BSD-2-Clause
#include "synthetic_people.h"

#include <algorithm>
#include <cmath>

namespace calped::selfcal_test {

CameraModel sceneCamera(const SceneConfig &c)
{
	CameraModel camera;
	makeSelfCalibratedCamera(c.focal, c.tilt, c.roll, c.height, (c.width - 1) / 2.0,
				 (c.height_px - 1) / 2.0, camera);
	return camera;
}

std::vector<PersonObservation> makeObservations(const SceneConfig &c, uint64_t frameStep)
{
	const CameraModel camera = sceneCamera(c);
	std::mt19937 rng(c.seed);
	std::uniform_real_distribution<double> uniform(0, 1);
	std::normal_distribution<double> normal(0, 1);
	std::vector<PersonObservation> out;
	const double horizon = std::max(0.0, camera.horizonRow((c.width - 1) / 2.0));
	uint64_t frame = 0;
	for (int attempts = 0; int(out.size()) < c.people && attempts < 200 * c.people; attempts++) {
		const Eigen::Vector2d foot(uniform(rng) * (c.width - 1),
					   horizon + uniform(rng) * (c.height_px - 1 - horizon));
		Eigen::Vector2d ground;
		if (!camera.groundPoint(foot, ground))
			continue;
		double h = c.personHeight + c.personHeightSd * normal(rng);
		const int kind = uniform(rng) < c.outlierFraction ? 1 + int(uniform(rng) * 4) : 0;
		if (kind == 1)
			h *= 0.6; // sitting
		Eigen::Vector2d head;
		if (!camera.headPoint(foot, h, head))
			continue;
		double top = head.y(), bottom = foot.y();
		if (c.boxesSpanHeadAndFoot && top > bottom)
			std::swap(top, bottom);
		if (kind == 2)
			bottom -= (0.2 + 0.4 * uniform(rng)) * (bottom - top); // cut off (occluded legs)
		if (kind == 3)
			top -= (0.3 + 0.7 * uniform(rng)) * (bottom - top); // merged with a person behind
		if (kind == 4) { // a false positive anywhere
			bottom = uniform(rng) * (c.height_px - 1);
			top = bottom - (c.minBoxHeight + uniform(rng) * 0.4 * c.height_px);
		}
		top += c.pixelNoise * normal(rng);
		bottom += c.pixelNoise * normal(rng);
		const double u = foot.x() + c.pixelNoise * normal(rng);
		const double w = 0.41 * (bottom - top);
		if (bottom - top < c.minBoxHeight || top < 2 || bottom > c.height_px - 3 || u - w / 2 < 2 ||
		    u + w / 2 > c.width - 3)
			continue;
		PersonObservation o;
		o.footU = float(u);
		o.footV = float(bottom);
		o.headV = float(top);
		o.frame = frame;
		frame += frameStep;
		out.push_back(o);
	}
	return out;
}

SelfCalibrationVerdict calibrate(const std::vector<PersonObservation> &observations,
				 const SceneConfig &scene, SelfCalibrationResult &result,
				 SelfCalibrationConfig config)
{
	config.maxObservations = std::max<int>(16, int(observations.size()));
	config.personHeight = scene.personHeight;
	SelfCalibrator calibrator(config);
	for (const PersonObservation &o : observations)
		calibrator.addObservation(o, scene.width, scene.height_px);
	return calibrator.estimate(result);
}

} // namespace calped::selfcal_test
