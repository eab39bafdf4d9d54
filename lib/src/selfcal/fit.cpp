// SPDX-License-Identifier: BSD-2-Clause
// Self-calibration fit (docs/calibration.md, "Self-calibration"): a robust linear model of
// pixel height against foot position gives the horizon and the checks for degenerate input;
// then a maximum-likelihood fit of (log f, tilt, roll, log height) to the world heights of
// the boxes (damped Newton, Cauchy loss, then least squares on the inliers, whose Hessian
// gives the covariance).
#include "selfcal/fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace calped {

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

double quantile(std::vector<double> v, double q)
{
	if (v.empty())
		return NAN;
	const size_t k = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
	std::nth_element(v.begin(), v.begin() + long(k), v.end());
	return v[k];
}

// Pixel height modelled as linear in the foot position: ph = a v + b u + c. Zero on the
// horizon for a camera that is not too wide (exact for a level camera).
struct LinearModel {
	double a = 0, b = 0, c = 0;
	int inliers = 0;
	double predict(double u, double v) const { return a * v + b * u + c; }
};

bool solveLinear(const std::vector<PersonObservation> &obs, const std::vector<int> &use,
		 LinearModel &m)
{
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
	Eigen::Vector3d y = Eigen::Vector3d::Zero();
	for (int i : use) {
		const PersonObservation &o = obs[size_t(i)];
		const double ph = o.footV - o.headV;
		// Relative residuals: weight 1 / ph^2.
		const Eigen::Vector3d x(o.footV / ph, o.footU / ph, 1 / ph);
		A += x * x.transpose();
		y += x;
	}
	if (std::abs(A.determinant()) < 1e-30)
		return false;
	const Eigen::Vector3d s = A.ldlt().solve(y);
	m.a = s(0);
	m.b = s(1);
	m.c = s(2);
	return std::isfinite(m.a + m.b + m.c);
}

// RANSAC over three observations (a fixed-seed generator: the same buffer gives the same
// answer), then least squares on the inliers: relative residual below `tolerance`.
LinearModel robustLinear(const std::vector<PersonObservation> &obs, int first, int last,
			 double tolerance, std::vector<char> *inlierMask)
{
	LinearModel best;
	const int n = last - first;
	if (n < 3)
		return best;
	uint64_t state = 0x9e3779b97f4a7c15ull;
	auto next = [&](int range) {
		state = state * 6364136223846793005ull + 1442695040888963407ull;
		return int((state >> 33) % uint64_t(range));
	};
	auto countInliers = [&](const LinearModel &m, std::vector<int> *members) {
		int k = 0;
		for (int i = first; i < last; i++) {
			const PersonObservation &o = obs[size_t(i)];
			const double ph = o.footV - o.headV;
			if (std::abs(m.predict(o.footU, o.footV) - ph) < tolerance * ph) {
				k++;
				if (members)
					members->push_back(i);
			}
		}
		return k;
	};
	std::vector<int> sample(3);
	for (int iteration = 0; iteration < 400; iteration++) {
		for (int j = 0; j < 3; j++)
			sample[size_t(j)] = first + next(n);
		LinearModel m;
		if (!solveLinear(obs, sample, m))
			continue;
		m.inliers = countInliers(m, nullptr);
		if (m.inliers > best.inliers)
			best = m;
	}
	for (int refine = 0; refine < 3 && best.inliers >= 3; refine++) {
		std::vector<int> members;
		countInliers(best, &members);
		LinearModel m;
		if (!solveLinear(obs, members, m))
			break;
		m.inliers = countInliers(m, nullptr);
		if (m.inliers < best.inliers)
			break;
		best = m;
	}
	if (inlierMask) {
		inlierMask->assign(obs.size(), 0);
		for (int i = first; i < last; i++) {
			const PersonObservation &o = obs[size_t(i)];
			const double ph = o.footV - o.headV;
			(*inlierMask)[size_t(i)] = std::abs(best.predict(o.footU, o.footV) - ph) < tolerance * ph;
		}
	}
	return best;
}

// The camera being fitted: x = (log f, tilt, roll, log height).
struct Geometry {
	Matrix34d P;
	Eigen::Matrix3d backProject; // R^T K^-1
	double height = 0;

	Geometry(const Vec4 &x, double cu, double cv)
	{
		const double f = std::exp(x(0));
		Eigen::Matrix3d K;
		K << f, 0, cu, 0, f, cv, 0, 0, 1;
		const Eigen::Matrix3d R = selfCalibrationRotation(x(1), x(2));
		height = std::exp(x(3));
		P.leftCols<3>() = K * R;
		P.col(3) = K * (-R * Eigen::Vector3d(0, 0, height));
		Eigen::Matrix3d Kinv;
		Kinv << 1 / f, 0, -cu / f, 0, 1 / f, -cv / f, 0, 0, 1;
		backProject = R.transpose() * Kinv;
	}

	// World height of the box (eq. 2.8 as CameraModel::worldHeight); NaN above the horizon.
	double worldHeight(const PersonObservation &o) const
	{
		const Eigen::Vector3d d = backProject * Eigen::Vector3d(o.footU, o.footV, 1);
		if (!(d.z() < -1e-9))
			return NAN;
		const double s = -height / d.z();
		const Eigen::Vector4d ground(s * d.x(), s * d.y(), 0, 1);
		const double depth = P.row(2).dot(ground);
		const double denominator = P(1, 2) - double(o.headV) * P(2, 2);
		return (double(o.headV) - double(o.footV)) * depth / denominator;
	}

	// The change of variables from the person's height to the head row: log |d log h / d vh|
	// up to a constant, log |vv - vf| - log |vv - vh| with vv the vertical vanishing point's
	// row (written without dividing by P33, which is 0 for a level camera). Leaving it out
	// of the likelihood biases the focal length (a tall person's head row is a noisy
	// regressor).
	double headRowJacobian(const PersonObservation &o) const
	{
		return std::log(std::abs(P(1, 2) - double(o.footV) * P(2, 2))) -
		       std::log(std::abs(P(1, 2) - double(o.headV) * P(2, 2)));
	}
};

struct Problem {
	const std::vector<PersonObservation> &obs;
	const SelfCalibrationConfig &config;
	double cu, cv, logFocalPrior;
	std::vector<double> sigma; // sd of each observation's log height

	// Normalised residuals of `use`, then the focal prior. Above the horizon: 10 sd.
	void residuals(const Vec4 &x, const std::vector<int> &use, Eigen::VectorXd &r) const
	{
		const Geometry g(x, cu, cv);
		r.resize(long(use.size()) + 1);
		for (size_t k = 0; k < use.size(); k++) {
			const size_t i = size_t(use[k]);
			const double h = g.worldHeight(obs[i]);
			// Log ratio: a person's height multiplies the box's, so a plain ratio would
			// weight tall people more and bias the fit (by var(h) / mean^2).
			r(long(k)) = std::isfinite(h) && h > 0 ? std::log(h / config.personHeight) / sigma[i] : 10.0;
		}
		// The focal prior (SelfCalibrationConfig::focalPrior).
		r(long(use.size())) = (x(0) - logFocalPrior) / config.focalPriorLogSd;
	}

	// Negative log-likelihood: Cauchy loss at scale c (c huge: least squares) on the
	// normalised log heights, the head-row Jacobian, the focal prior.
	double objective(const Vec4 &x, const std::vector<int> &use, double c) const
	{
		const Geometry g(x, cu, cv);
		double total = 0;
		for (int i : use) {
			const PersonObservation &o = obs[size_t(i)];
			const double h = g.worldHeight(o);
			const double r = std::isfinite(h) && h > 0 ? std::log(h / config.personHeight) / sigma[size_t(i)] : 10.0;
			total += c > 1e5 ? 0.5 * r * r : 0.5 * c * c * std::log1p((r / c) * (r / c));
			total -= g.headRowJacobian(o);
		}
		const double prior = (x(0) - logFocalPrior) / config.focalPriorLogSd;
		return total + 0.5 * prior * prior;
	}
};

double robustScale(const Eigen::VectorXd &r, long n)
{
	std::vector<double> a(static_cast<size_t>(n));
	for (long i = 0; i < n; i++)
		a[size_t(i)] = std::abs(r(i));
	return std::max(1.4826 * quantile(a, 0.5), 1e-3);
}

double cauchyCost(const Eigen::VectorXd &r, double c)
{
	double cost = 0;
	const long n = r.size() - 1;
	for (long i = 0; i < n; i++)
		cost += std::log1p((r(i) / c) * (r(i) / c));
	return cost + r(n) * r(n);
}

// Damped Newton on the objective with a numerical gradient and Hessian (four parameters:
// cheap). Returns the Hessian at the end in `hessian`.
double minimise(const Problem &problem, const std::vector<int> &use, double c, Vec4 &x,
		Mat4 *hessian = nullptr)
{
	const double step = 1e-4;
	auto F = [&](const Vec4 &v) { return problem.objective(v, use, c); };
	auto derivatives = [&](const Vec4 &v, Vec4 &g, Mat4 &H) {
		const double f0 = F(v);
		for (int i = 0; i < 4; i++) {
			Vec4 a = v, b = v;
			a(i) += step;
			b(i) -= step;
			const double fa = F(a), fb = F(b);
			g(i) = (fa - fb) / (2 * step);
			H(i, i) = (fa - 2 * f0 + fb) / (step * step);
			for (int j = 0; j < i; j++) {
				Vec4 pp = v, pm = v, mp = v, mm = v;
				pp(i) += step; pp(j) += step;
				pm(i) += step; pm(j) -= step;
				mp(i) -= step; mp(j) += step;
				mm(i) -= step; mm(j) -= step;
				H(i, j) = H(j, i) = (F(pp) - F(pm) - F(mp) + F(mm)) / (4 * step * step);
			}
		}
		return f0;
	};
	double cost = F(x), lambda = 1e-3;
	Vec4 g;
	Mat4 H;
	for (int iteration = 0; iteration < 80; iteration++) {
		derivatives(x, g, H);
		bool improved = false;
		for (int tries = 0; tries < 12 && !improved; tries++) {
			Mat4 damped = H;
			const double scale = std::max(H.diagonal().cwiseAbs().maxCoeff(), 1.0);
			damped.diagonal().array() += lambda * scale;
			const Vec4 delta = damped.ldlt().solve(-g);
			Vec4 candidate = x + delta;
			candidate(1) = std::clamp(candidate(1), -1.4, 1.56);
			const double cc = F(candidate);
			if (std::isfinite(cc) && cc < cost) {
				improved = true;
				const double gain = cost - cc;
				x = candidate;
				cost = cc;
				lambda = std::max(lambda / 4, 1e-12);
				if (gain < 1e-9 * (1 + std::abs(cost)))
					iteration = 1000;
			} else {
				lambda *= 8;
			}
		}
		if (!improved)
			break;
	}
	if (hessian) {
		derivatives(x, g, H);
		*hessian = H;
	}
	return cost;
}

SelfCalibrationVerdict verdict(SelfCalibrationResult &out, SelfCalibrationVerdict v,
			       const std::string &message)
{
	out.verdict = v;
	out.message = message;
	return v;
}

std::string format(const char *fmt, double a = 0, double b = 0, double c = 0, double d = 0)
{
	char text[320];
	std::snprintf(text, sizeof(text), fmt, a, b, c, d);
	return text;
}

} // namespace

SelfCalibrationVerdict fitSelfCalibration(const std::vector<PersonObservation> &obs,
					  int width, int height, const SelfCalibrationConfig &config,
					  SelfCalibrationResult &out)
{
	using V = SelfCalibrationVerdict;
	const double cu = config.principalU >= 0 ? config.principalU : (width - 1) / 2.0;
	const double cv = config.principalV >= 0 ? config.principalV : (height - 1) / 2.0;
	out.principalU = cu;
	out.principalV = cv;
	const int n = int(obs.size());
	out.observations = n;
	if (n < config.minInliers)
		return verdict(out, V::TooFewPeople,
			       format("too few people: %.0f usable boxes, at least %.0f needed (confident, "
				      "whole, upright detections)", n, config.minInliers));

	// One person standing still: every foot in one spot.
	{
		double su = 0, sv = 0, suu = 0, svv = 0;
		for (const PersonObservation &o : obs) {
			su += o.footU;
			sv += o.footV;
			suu += double(o.footU) * o.footU;
			svv += double(o.footV) * o.footV;
		}
		const double var = (suu - su * su / n + svv - sv * sv / n) / n;
		const double spread = std::sqrt(std::max(var, 0.0)) / std::hypot(width, height);
		if (spread < config.minFootSpread)
			return verdict(out, V::OnePlace,
				       format("all %.0f observations come from one place (foot spread %.3f of "
					      "the image diagonal, at least %.3f needed): one person standing "
					      "still, or a false positive on the scene", n, spread,
					      config.minFootSpread));
	}

	std::vector<char> mask;
	const LinearModel line = robustLinear(obs, 0, n, 0.15, &mask);
	std::vector<double> footRows, heights;
	std::vector<int> lineInliers;
	for (int i = 0; i < n; i++)
		if (mask[size_t(i)]) {
			lineInliers.push_back(i);
			footRows.push_back(obs[size_t(i)].footV);
			heights.push_back(obs[size_t(i)].footV - obs[size_t(i)].headV);
		}
	if (line.inliers < config.minInliers)
		return verdict(out, V::TooFewPeople,
			       format("too few consistent people: %.0f of %.0f boxes agree on one ground "
				      "plane, at least %.0f needed", line.inliers, n, config.minInliers));
	const double rowLow = quantile(footRows, 0.1), rowHigh = quantile(footRows, 0.9);
	out.footRowSpread = (rowHigh - rowLow) / height;
	if (out.footRowSpread < config.minDepthSpread)
		return verdict(out, V::TooLittleDepthSpread,
			       format("too little spread in depth: the people's feet span %.1f%% of the image "
				      "height (10-90%%), at least %.0f%% needed", 100 * out.footRowSpread,
				      100 * config.minDepthSpread));

	// Heights that do not grow towards the bottom of the image, or people on both sides of
	// the "horizon": the head-foot lines radiate from a point inside the image.
	const double medianHeight = quantile(heights, 0.5);
	const double growth = line.a * (rowHigh - rowLow) / medianHeight;
	const double horizonAtCentre = -(line.b * cu + line.c) / line.a;
	int aboveHorizon = 0;
	for (const PersonObservation &o : obs)
		if (line.a > 0 && o.footV < -(line.b * o.footU + line.c) / line.a)
			aboveHorizon++;
	// A steep camera bends pixel height against row (the vertical vanishing point is near):
	// low growth alone is straight down only where the linear model does not explain most
	// boxes either.
	const bool linearFitsPoorly = line.inliers < n / 2;
	if ((aboveHorizon > n / 5 || growth < 0.1) && n >= 3 * config.minInliers) {
		// Unless the first and last thirds each look like a proper camera on their own: then
		// it is the camera that moved between them (a pan mixes their rows).
		auto thirdGrows = [&](int first, int last) {
			const LinearModel m = robustLinear(obs, first, last, 0.15, nullptr);
			std::vector<double> rows, ph;
			for (int i = first; i < last; i++) {
				rows.push_back(obs[size_t(i)].footV);
				ph.push_back(obs[size_t(i)].footV - obs[size_t(i)].headV);
			}
			const double g = m.a * (quantile(rows, 0.9) - quantile(rows, 0.1)) / quantile(ph, 0.5);
			return m.inliers >= config.minInliers / 2 && g >= 0.1 ? -(m.b * cu + m.c) / m.a : NAN;
		};
		const double early = thirdGrows(0, n / 3), late = thirdGrows(n - n / 3, n);
		if (std::isfinite(early) && std::isfinite(late) && std::abs(early - late) > 0.05 * height)
			return verdict(out, V::CameraMoving,
				       format("the camera moved: the first and last third of the observations each "
					      "fit a camera (horizon rows %.0f and %.0f) but not together (box "
					      "heights change by %.0f%% over all)", early, late, 100 * growth));
	}
	if (aboveHorizon > n / 5 || (growth < 0.1 && linearFitsPoorly))
		return verdict(out, V::LookingStraightDown,
			       format("the camera looks (nearly) straight down: box heights change by %.0f%% "
				      "from the far to the near people (%.0f of %.0f feet above the fitted "
				      "horizon); heights must grow towards the bottom of the image",
				      100 * growth, aboveHorizon, n));

	Problem problem{ obs, config, cu, cv,
			 std::log(config.focalPrior > 0 ? config.focalPrior : std::hypot(width, height)), {} };
	problem.sigma.resize(size_t(n));
	const double relativeSd = config.personHeightSd / config.personHeight;
	for (int i = 0; i < n; i++) {
		// From the expected pixel height, not the observed one (which grows with the
		// person's height and would again favour tall people).
		const PersonObservation &o = obs[size_t(i)];
		const double ph = std::max(line.predict(o.footU, o.footV), 0.5 * (o.footV - o.headV));
		problem.sigma[size_t(i)] = std::sqrt(relativeSd * relativeSd +
						     2 * (config.pixelNoise / ph) * (config.pixelNoise / ph));
	}

	// Start: the horizon and roll of the linear model, focal from a grid, height scaled so
	// that the median box is personHeight tall.
	const double roll0 = std::atan(-line.b / line.a);
	const double horizonDistance = (cv - horizonAtCentre) * std::cos(roll0);
	// Selection bias: where a tall (and so wide) person's box would leave the frame, or a
	// short person's box would be below minBoxHeight, only the others are seen and heights
	// look biased; leave out every observation at such positions (whoever it is).
	std::vector<int> all;
	for (int i = 0; i < n; i++) {
		const PersonObservation &o = obs[size_t(i)];
		const double expected = line.predict(o.footU, o.footV);
		const double halfWidth = 0.65 * config.maxAspect * expected;
		if (o.footV - 1.3 * expected > config.borderMargin + 1 &&
		    0.75 * expected > config.minBoxHeight &&
		    o.footU - halfWidth > config.borderMargin + 1 &&
		    o.footU + halfWidth < width - config.borderMargin - 1)
			all.push_back(i);
	}
	if (int(all.size()) < config.minInliers)
		return verdict(out, V::TooFewPeople,
			       format("too few people away from the frame's top and the detector's smallest "
				      "size: %.0f of %.0f, at least %.0f needed", double(all.size()), n,
				      config.minInliers));
	Vec4 best;
	double bestCost = INFINITY;
	Eigen::VectorXd r;
	const double diagonal = std::hypot(width, height);
	for (int k = 0; k <= 24 * 18; k++) {
		// Focal lengths from a quarter to five diagonals; the tilt from the linear model's
		// horizon, then every 5 degrees (steep cameras bend that model).
		const double f = diagonal * 0.25 * std::pow(20.0, (k % 25) / 24.0);
		const int tiltStep = k / 25;
		const double tilt = tiltStep == 0 ? std::atan(horizonDistance / f) : (tiltStep - 1) * 5 * M_PI / 180;
		Vec4 x(std::log(f), tilt, roll0, 0);
		const Geometry g(x, cu, cv);
		std::vector<double> h;
		for (int i : all) {
			const double v = g.worldHeight(obs[size_t(i)]);
			if (std::isfinite(v) && v > 0)
				h.push_back(v);
		}
		if (h.size() < 3)
			continue;
		x(3) = std::log(config.personHeight / quantile(h, 0.5));
		problem.residuals(x, all, r);
		const double cost = cauchyCost(r, 3.0);
		if (cost < bestCost) {
			bestCost = cost;
			best = x;
		}
	}
	if (!std::isfinite(bestCost))
		return verdict(out, V::NotConverged, "no starting camera puts the people's feet below the horizon");

	Vec4 x = best;
	minimise(problem, all, 3.0, x);
	problem.residuals(x, all, r);
	const long used = long(all.size());
	double scale = robustScale(r, used);
	minimise(problem, all, 2.385 * scale, x);

	// Inliers within 3 robust sd; plain least squares on them for the covariance.
	problem.residuals(x, all, r);
	scale = robustScale(r, used);
	std::vector<int> inliers;
	for (long k = 0; k < used; k++)
		if (std::abs(r(k)) < 3 * scale)
			inliers.push_back(all[size_t(k)]);
	if (int(inliers.size()) < config.minInliers)
		return verdict(out, V::TooFewPeople,
			       format("too few consistent people after the fit: %.0f inliers of %.0f, at "
				      "least %.0f needed", double(inliers.size()), n, config.minInliers));
	Mat4 hessian;
	minimise(problem, inliers, 1e6, x, &hessian); // plain least squares on the inliers
	problem.residuals(x, inliers, r);
	const long m = long(inliers.size());
	// The Hessian assumes the configured spread; scale by the spread the residuals show.
	const double variance = r.head(m).squaredNorm() / double(std::max<long>(m - 4, 1));
	Eigen::FullPivLU<Mat4> lu(hessian);
	if (!lu.isInvertible() || !x.allFinite())
		return verdict(out, V::NotConverged, "the fit is singular: the boxes do not determine the camera");
	Mat4 covariance = lu.inverse() * std::max(variance, 1.0);
	for (int i = 0; i < 4; i++)
		covariance(i, i) = std::abs(covariance(i, i));
	const double f = std::exp(x(0)), camHeight = std::exp(x(3));
	out.focal = { f, f * std::sqrt(covariance(0, 0)) };
	out.tilt = { x(1), std::sqrt(covariance(1, 1)) };
	out.roll = { x(2), std::sqrt(covariance(2, 2)) };
	out.height = { camHeight, camHeight * std::sqrt(covariance(3, 3)) };
	out.inliers = int(m);
	double rms = 0;
	{
		const Geometry g(x, cu, cv);
		for (int i : inliers) {
			const double h = g.worldHeight(obs[size_t(i)]) / config.personHeight - 1;
			rms += h * h;
		}
		rms = std::sqrt(rms / double(m));
	}
	out.residual = rms;
	out.horizonRow = cv - f * std::tan(x(1)) / std::cos(x(2));

	// Camera moving: with the one camera fitted to all, the people of the first third of the
	// buffer (in time) come out taller or shorter than those of the last third.
	if (n >= 3 * config.minInliers) {
		const Geometry g(x, cu, cv);
		auto medianResidual = [&](int first, int last) {
			std::vector<double> v;
			for (int i = first; i < last; i++) {
				const double h = g.worldHeight(obs[size_t(i)]);
				if (std::isfinite(h))
					v.push_back(h / config.personHeight - 1);
			}
			return quantile(v, 0.5);
		};
		const double early = medianResidual(0, n / 3), late = medianResidual(n - n / 3, n);
		const double shift = std::abs(early - late);
		if (!(shift <= config.maxHeightShift))
			return verdict(out, V::CameraMoving,
				       format("the camera moved: with one camera fitted to all, the people of the "
					      "first third of the observations come out %+.0f%% and those of the last "
					      "third %+.0f%% off the mean height (at most %.0f%% apart allowed)",
					      100 * early, 100 * late, 100 * config.maxHeightShift));
	}
	if (x(1) > config.maxTilt)
		return verdict(out, V::LookingStraightDown,
			       format("the camera looks (nearly) straight down: tilt %.1f degrees, at most "
				      "%.1f allowed", x(1) * 180 / M_PI, config.maxTilt * 180 / M_PI));
	if (!(out.height.sd / camHeight <= config.maxRelativeSd))
		return verdict(out, V::NotConverged,
			       format("not converged: camera height %.2f m +- %.1f%%, at most %.1f%% allowed",
				      camHeight, 100 * out.height.sd / camHeight, 100 * config.maxRelativeSd));
	const Status st = makeSelfCalibratedCamera(f, x(1), x(2), camHeight, cu, cv, out.camera);
	if (!st.ok())
		return verdict(out, V::NotConverged, st.message());
	const bool focalWeak = out.focal.sd > 0.2 * f;
	return verdict(out, V::Ok,
		       format("calibrated from %.0f of %.0f observations", double(m), n) +
			       (focalWeak ? " (focal length weakly determined: the camera is nearly level, "
					    "heights depend little on it)"
					  : ""));
}

} // namespace calped
