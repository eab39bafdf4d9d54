// SPDX-License-Identifier: BSD-2-Clause
// Self-calibration on synthetic cameras (docs/calibration.md, "Synthetic accuracy"): heights
// 2-15 m, tilts 0-60 degrees, focal lengths 400-2000 px, 1280 x 720, person heights
// N(1.7, 0.08) m, 2 px noise on head and foot rows, 20% outliers. Prints a Markdown table:
// the median error of each parameter over the seeds with 1000 people, and the number of
// people needed for 5% error in camera height and in focal length.
//   build/bench/selfcal_synthetic [--seeds N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "synthetic_people.h"

using namespace calped;
using namespace calped::selfcal_test;

namespace {

struct Errors {
	double focal = NAN, tilt = NAN, height = NAN, horizon = NAN; // %, degrees, %, px
	int failed = 0;
};

double median(std::vector<double> v)
{
	if (v.empty())
		return NAN;
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}

Errors run(SceneConfig scene, int people, int seeds)
{
	std::vector<double> f, t, h, v;
	Errors e;
	CameraParameters truth;
	cameraParameters(sceneCamera(scene), (scene.width - 1) / 2.0, truth);
	for (int s = 0; s < seeds; s++) {
		scene.people = people;
		scene.seed = uint32_t(1000 + s);
		SelfCalibrationResult r;
		if (calibrate(makeObservations(scene), scene, r) != SelfCalibrationVerdict::Ok) {
			e.failed++;
			continue;
		}
		f.push_back(100 * std::abs(r.focal.value / scene.focal - 1));
		t.push_back(std::abs(r.tilt.value - scene.tilt) * 180 / M_PI);
		h.push_back(100 * std::abs(r.height.value / scene.height - 1));
		v.push_back(std::abs(r.horizonRow - truth.horizonRow));
	}
	if (e.failed * 2 <= seeds) {
		e.focal = median(f);
		e.tilt = median(t);
		e.height = median(h);
		e.horizon = median(v);
	}
	return e;
}

} // namespace

int main(int argc, char **argv)
{
	int seeds = 3;
	for (int i = 1; i + 1 < argc; i++)
		if (!std::strcmp(argv[i], "--seeds"))
			seeds = std::max(1, std::atoi(argv[i + 1]));
	const int ladder[] = { 100, 300, 1000, 3000 };
	std::printf("| height m | tilt deg | focal px | focal err %% | tilt err deg | height err %% | horizon err px | failed | people for height 5%% | people for focal 5%% |\n");
	std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
	for (double height : { 2.0, 4.0, 8.0, 15.0 })
		for (double tilt : { 0.0, 15.0, 30.0, 45.0, 60.0 })
			for (double focal : { 400.0, 1000.0, 2000.0 }) {
				SceneConfig scene;
				scene.height = height;
				scene.tilt = tilt * M_PI / 180;
				scene.focal = focal;
				scene.outlierFraction = 0.2;
				const Errors at1000 = run(scene, 1000, seeds);
				int forHeight = 0, forFocal = 0;
				for (int n : ladder) {
					const Errors e = n == 1000 ? at1000 : run(scene, n, seeds);
					if (!forHeight && e.height <= 5)
						forHeight = n;
					if (!forFocal && e.focal <= 5)
						forFocal = n;
				}
				char nh[16] = "> 3000", nf[16] = "> 3000";
				if (forHeight)
					std::snprintf(nh, sizeof(nh), "%d", forHeight);
				if (forFocal)
					std::snprintf(nf, sizeof(nf), "%d", forFocal);
				std::printf("| %.0f | %.0f | %.0f | %.1f | %.2f | %.1f | %.1f | %d/%d | %s | %s |\n", height, tilt,
					    focal, at1000.focal, at1000.tilt, at1000.height, at1000.horizon,
					    at1000.failed, seeds, nh, nf);
				std::fflush(stdout);
			}
	return 0;
}
