// SPDX-License-Identifier: BSD-2-Clause
// Can the lean of people in the image fix the focal length? (issue 16; docs/calibration.md,
// "Lean"). With a tilted camera vertical lines meet at the vertical vanishing point (U, V),
// so a person whose foot is at (u, v) and whose box is h pixels tall has the head shifted
// sideways by lean = (u - U) h / (V - v), and with the principal point at the image centre
// and the horizon at row vh, (V - cy)(cy - vh) = f^2. For every whole, unoccluded
// ground-truth box this compares the lean the reference camera predicts (Tsai, distortion
// included) with two measurements from the pixels inside the box:
//   foreground  column centroid of |frame - background| > threshold (background: per-pixel
//               median of every 8th frame), top third of the box minus bottom third, x 1.5
//               (the thirds' centroids are 2/3 of the height apart);
//   gradient    the same with the gradient magnitude as weight.
// Then fits (U, V) to each set of leans (the predicted ones too: what the pinhole formula
// makes of the lens distortion) and prints the focal length each gives.
// Usage: selfcal_lean --frames DIR --gt FILE --calib FILE [--max-frames N] [--min-height H]
//                     [--threshold T] [--list]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <calped/calped.h>

#include "boxes.h"
#include "frame_source.h"
#include "ground_truth.h"
#include "image_io.h"
#include "program.h"

using namespace calped;
using namespace calped::eval_tool;

namespace {

struct Person {
	double u, v, h;          // foot column and row, box height (pixels)
	double predicted;        // lean by the reference camera
	// Measured leans (NaN when too little signal): foreground thirds, the same with the
	// thirds' own row centroids, the foreground's per-row centroid line, gradient thirds.
	double foreground, foregroundRows, foregroundLine, gradient;
	long frame;
};

const apps::ProgramInfo kProgram = {
	"selfcal_lean",
	"usage: selfcal_lean --frames DIR --gt FILE --calib FILE [options]\n"
	"\n"
	"Whether people's lean in the image fixes the focal length (docs/calibration.md).\n"
	"\n"
	"options:\n",
	"",
};

std::vector<uint8_t> grey(const ports::RgbImage &image)
{
	std::vector<uint8_t> g(size_t(image.width) * size_t(image.height));
	for (size_t i = 0; i < g.size(); ++i) {
		const uint8_t *p = &image.pixels[3 * i];
		g[i] = uint8_t((77 * p[0] + 150 * p[1] + 29 * p[2]) >> 8);
	}
	return g;
}

// Column centroid of `weight` over rows [r0, r1) and columns [c0, c1); NaN without weight.
template <typename Weight>
double centroid(int r0, int r1, int c0, int c1, Weight weight, double &mass, double &row)
{
	double sum = 0, sumX = 0, sumY = 0;
	for (int r = r0; r < r1; ++r)
		for (int c = c0; c < c1; ++c) {
			const double w = weight(r, c);
			sum += w;
			sumX += w * c;
			sumY += w * r;
		}
	mass = sum;
	row = sum > 0 ? sumY / sum : NAN;
	return sum > 0 ? sumX / sum : NAN;
}

// Lean from the line through each row's weighted column centroid (rows weighted by their
// mass): minus the slope times the box height.
template <typename Weight>
double centroidLine(int r0, int r1, int c0, int c1, double h, Weight weight)
{
	double sw = 0, sr = 0, sx = 0, srr = 0, srx = 0;
	for (int r = r0; r < r1; ++r) {
		double m = 0, mx = 0;
		for (int c = c0; c < c1; ++c) {
			const double w = weight(r, c);
			m += w;
			mx += w * c;
		}
		if (m <= 0)
			continue;
		const double x = mx / m;
		sw += m;
		sr += m * r;
		sx += m * x;
		srr += m * r * r;
		srx += m * r * x;
	}
	const double var = srr / sw - (sr / sw) * (sr / sw);
	return sw > 0 && var > 0 ? -h * (srx / sw - (sr / sw) * (sx / sw)) / var : NAN;
}

// U for a given V: the lean m = (u - U) h / (V - v) is linear in U. Least squares over the
// people whose residual (at the previous U) is within `clip`, all when clip is infinite.
double fitU(const std::vector<Person> &people, double Person::*lean, double V, double U0,
	    double clip)
{
	double sab = 0, sbb = 0;
	for (const Person &p : people) {
		const double m = p.*lean, b = p.h / (V - p.v);
		if (std::isnan(m) || std::abs(m - (p.u - U0) * b) > clip)
			continue;
		sab += (p.u * b - m) * b;
		sbb += b * b;
	}
	return sbb > 0 ? sab / sbb : U0;
}

// Vertical vanishing point (U, V) fitted to leans: V on a log grid below the image, U in
// closed form, cost sum min(r^2, clip^2) with clip 3 robust sd of the leans themselves.
double fitVanishingPoint(const std::vector<Person> &people, double Person::*lean, double &U,
			 double &rms, int &used)
{
	std::vector<double> spread;
	for (const Person &p : people)
		if (!std::isnan(p.*lean))
			spread.push_back(std::abs(p.*lean));
	std::nth_element(spread.begin(), spread.begin() + long(spread.size() / 2), spread.end());
	const double clip = 3 * 1.4826 * spread[spread.size() / 2];
	double bestV = NAN, bestCost = INFINITY;
	for (double V = 700; V < 2e5; V *= 1.002) {
		double u = fitU(people, lean, V, 0, INFINITY);
		u = fitU(people, lean, V, u, clip);
		double cost = 0, inlierCost = 0;
		int n = 0;
		for (const Person &p : people) {
			const double m = p.*lean;
			if (std::isnan(m))
				continue;
			const double r = m - (p.u - u) * p.h / (V - p.v);
			cost += std::min(r * r, clip * clip);
			if (std::abs(r) <= clip) {
				inlierCost += r * r;
				++n;
			}
		}
		if (cost < bestCost) {
			bestCost = cost;
			bestV = V;
			U = u;
			used = n;
			rms = std::sqrt(inlierCost / std::max(n, 1));
		}
	}
	return bestV;
}

} // namespace

int main(int argc, char **argv)
{
	const std::vector<apps::OptionSpec> table = {
		{ "frames", "DIR", "the PNG frames, in name order" },
		{ "gt", "FILE", "ground truth (PETS CVML)" },
		{ "calib", "FILE", "the camera the leans are compared with" },
		{ "max-frames", "N", "only the first N frames" },
		{ "min-height", "H", "boxes at least H pixels tall (default 40)" },
		{ "threshold", "T", "foreground: |difference from the background| > T grey levels (default 25)" },
		{ "list", nullptr, "print every box's leans" },
	};
	apps::ParsedArgs args;
	const int rc = apps::parseCommandLine(kProgram, table, false, argc, argv, args);
	if (rc >= 0)
		return rc;
	std::string framesDir, gtPath, calibPath, error;
	long maxFrames = 0;
	double minHeight = 40, threshold = 25;
	bool list = false;
	for (const apps::ParsedOption &o : args.options) {
		if (o.name == "list")
			list = true;
		else if (o.name == "frames")
			apps::nonEmpty(o, "a folder", framesDir, error);
		else if (o.name == "gt")
			apps::nonEmpty(o, "a file name", gtPath, error);
		else if (o.name == "calib")
			apps::nonEmpty(o, "a file name", calibPath, error);
		else if (o.name == "max-frames")
			apps::wholeIn(o, 1, 1000000000, maxFrames, error);
		else if (o.name == "min-height")
			apps::numberIn(o, 0, true, 100000, minHeight, error);
		else if (o.name == "threshold")
			apps::numberIn(o, 0, true, 255, threshold, error);
		if (!error.empty())
			return apps::usageError(kProgram, error);
	}
	if (framesDir.empty() || gtPath.empty() || calibPath.empty())
		return apps::usageError(kProgram, "needs --frames, --gt and --calib (try --help)");

	std::vector<uint8_t> bytes;
	CameraModel camera;
	if (!ports::readFileBytes(calibPath, bytes, error, "calibration ", ports::kMaxModelFileBytes)) {
		std::fprintf(stderr, "selfcal_lean: %s\n", error.c_str());
		return 1;
	}
	if (Status st = loadCalibration(reinterpret_cast<const char *>(bytes.data()), bytes.size(),
					calibPath.c_str(), camera);
	    !st.ok()) {
		std::fprintf(stderr, "selfcal_lean: %s\n", st.message());
		return 1;
	}
	GroundTruth truth;
	FrameInput input;
	if (!loadGroundTruth(gtPath, truth, error) ||
	    !resolveFolderInput(framesDir, maxFrames, input, error)) {
		std::fprintf(stderr, "selfcal_lean: %s\n", error.c_str());
		return 1;
	}
	const int W = input.width, H = input.height;

	// Background: per-pixel median of every 8th frame of the whole folder.
	std::vector<std::vector<uint8_t>> samples;
	{
		FrameInput all;
		if (!resolveFolderInput(framesDir, 0, all, error)) {
			std::fprintf(stderr, "selfcal_lean: %s\n", error.c_str());
			return 1;
		}
		std::unique_ptr<FrameSource> source = all.open(error);
		ports::RgbImage image;
		for (long k = 0; source && source->next(image, error); ++k)
			if (k % 8 == 0)
				samples.push_back(grey(image));
	}
	std::vector<uint8_t> background(size_t(W) * size_t(H));
	{
		std::vector<uint8_t> column(samples.size());
		for (size_t i = 0; i < background.size(); ++i) {
			for (size_t s = 0; s < samples.size(); ++s)
				column[s] = samples[s][i];
			std::nth_element(column.begin(), column.begin() + long(column.size() / 2), column.end());
			background[i] = column[column.size() / 2];
		}
	}
	samples.clear();

	CameraParameters reference;
	cameraParameters(camera, (W - 1) / 2.0, reference);
	std::vector<Person> people;
	std::unique_ptr<FrameSource> source = input.open(error);
	ports::RgbImage image;
	for (long frame = 1; source && source->next(image, error); ++frame) {
		const std::vector<uint8_t> g = grey(image);
		const std::vector<GtBox> &boxes = truth.boxes(frame);
		for (size_t i = 0; i < boxes.size(); ++i) {
			const Box &b = boxes[i].box;
			if (boxes[i].ignore || b.h < minHeight || b.x < 2 || b.y < 2 || b.x + b.w > W - 2 ||
			    b.y + b.h > H - 2)
				continue;
			bool alone = true; // no other person overlapping the box (widened by a quarter)
			const Box wide{ b.x - b.w / 4, b.y, b.w * 1.5, b.h };
			for (size_t j = 0; j < boxes.size() && alone; ++j)
				alone = j == i || intersectionOverUnion(wide, boxes[j].box) == 0;
			if (!alone)
				continue;
			Person p;
			p.u = b.x + b.w / 2;
			p.v = b.y + b.h;
			p.h = b.h;
			p.frame = frame;
			Eigen::Vector2d ground;
			const Eigen::Vector2d foot(p.u, p.v), head(p.u, b.y);
			const double worldHeight = camera.boxWorldHeight(foot, head);
			if (!camera.pixelToGround(foot, ground) || !std::isfinite(worldHeight))
				continue;
			p.predicted = camera.worldToPixel(Eigen::Vector3d(ground.x(), ground.y(), worldHeight)).x() - p.u;
			const int c0 = int(std::floor(b.x)), c1 = int(std::ceil(b.x + b.w));
			const int top0 = int(std::round(b.y)), top1 = int(std::round(b.y + b.h / 3));
			const int bot0 = int(std::round(b.y + 2 * b.h / 3)), bot1 = int(std::round(b.y + b.h));
			auto fg = [&](int r, int c) {
				const size_t k = size_t(r) * size_t(W) + size_t(c);
				return std::abs(int(g[k]) - int(background[k])) > threshold ? 1.0 : 0.0;
			};
			auto grad = [&](int r, int c) {
				if (r < 1 || c < 1 || r >= H - 1 || c >= W - 1)
					return 0.0;
				const size_t k = size_t(r) * size_t(W) + size_t(c);
				const double gx = double(g[k + 1]) - g[k - 1];
				const double gy = double(g[k + size_t(W)]) - g[k - size_t(W)];
				return std::sqrt(gx * gx + gy * gy);
			};
			double massTop, massBottom, rowTop, rowBottom;
			const double fTop = centroid(top0, top1, c0, c1, fg, massTop, rowTop);
			const double fBottom = centroid(bot0, bot1, c0, c1, fg, massBottom, rowBottom);
			const double area = b.w * b.h / 3;
			const bool enough = massTop > 0.15 * area && massBottom > 0.15 * area;
			p.foreground = enough ? 1.5 * (fTop - fBottom) : NAN;
			p.foregroundRows = enough ? (fTop - fBottom) * b.h / (rowBottom - rowTop) : NAN;
			p.foregroundLine = enough ? centroidLine(top0, bot1, c0, c1, b.h, fg) : NAN;
			const double gTop = centroid(top0, top1, c0, c1, grad, massTop, rowTop);
			const double gBottom = centroid(bot0, bot1, c0, c1, grad, massBottom, rowBottom);
			p.gradient = 1.5 * (gTop - gBottom);
			people.push_back(p);
			if (list)
				std::printf("%ld %.1f %.1f %.1f predicted %.2f foreground %.2f rows %.2f line "
					    "%.2f gradient %.2f\n",
					    frame, p.u, p.v, p.h, p.predicted, p.foreground, p.foregroundRows,
					    p.foregroundLine, p.gradient);
		}
	}

	std::printf("reference camera: focal %.1f px, tilt %.2f deg, roll %.2f deg, horizon row %.1f\n",
		    reference.focal, reference.tilt * 180 / M_PI, reference.roll * 180 / M_PI,
		    reference.horizonRow);
	const double cx = (W - 1) / 2.0, cy = (H - 1) / 2.0;
	// The vanishing point the pinhole part of the reference camera has.
	const double Vtrue = cy + reference.focal / std::tan(reference.tilt);
	std::printf("%zu whole, unoccluded boxes >= %.0f px in frames 1-%ld; pinhole V = %.0f\n",
		    people.size(), minHeight, input.maxFrames ? input.maxFrames : long(input.files.size()),
		    Vtrue);

	// Per column band: mean predicted and measured leans (boxes with a foreground measure).
	std::printf("\n| foot column - cx | boxes | predicted px | foreground thirds px | thirds, row "
		    "centroids px | row-centroid line px | gradient thirds px |\n"
		    "|---:|---:|---:|---:|---:|---:|---:|\n");
	for (double lo = -400; lo < 400; lo += 100) {
		double sum[5] = {};
		int n = 0;
		for (const Person &p : people)
			if (p.u - cx >= lo && p.u - cx < lo + 100 && !std::isnan(p.foregroundLine) &&
			    !std::isnan(p.foregroundRows)) {
				sum[0] += p.predicted;
				sum[1] += p.foreground;
				sum[2] += p.foregroundRows;
				sum[3] += p.foregroundLine;
				sum[4] += p.gradient;
				++n;
			}
		if (n)
			std::printf("| %.0f..%.0f | %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", lo, lo + 100,
				    n, sum[0] / n, sum[1] / n, sum[2] / n, sum[3] / n, sum[4] / n);
	}

	std::printf("\n| leans | boxes used | U | V | fit RMS px | focal px | focal error |\n|---|---:|---:|---:|---:|---:|---:|\n");
	const struct {
		const char *name;
		double Person::*lean;
	} sets[] = { { "predicted (Tsai)", &Person::predicted },
		     { "foreground thirds", &Person::foreground },
		     { "foreground thirds, their row centroids", &Person::foregroundRows },
		     { "foreground row-centroid line", &Person::foregroundLine },
		     { "gradient", &Person::gradient } };
	for (const auto &s : sets) {
		double U = 0, rms = 0;
		int used = 0;
		const double V = fitVanishingPoint(people, s.lean, U, rms, used);
		const double f2 = (V - cy) * (cy - reference.horizonRow);
		const double f = f2 > 0 ? std::sqrt(f2) : NAN;
		std::printf("| %s | %d | %.0f | %.0f | %.2f | %.0f | %+.1f%% |\n", s.name, used, U, V, rms,
			    f, 100 * (f / reference.focal - 1));
	}
	return 0;
}
