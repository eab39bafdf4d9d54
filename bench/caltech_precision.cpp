// SPDX-License-Identifier: BSD-2-Clause
// Where the Caltech+ orientation channels' distance from the toolbox comes from
// (docs/parity.md): level 1 of PETS frame 1 (scale 1, computed) with the Caltech+ options
// (shrink 2, softBin 1, no colour smoothing), computed by a float emulation of the
// toolbox's SSE path (its approximate reciprocals as Intel's rule gives them, its acos
// index, its gradHist with trilinear binning), with one stage at a time replaced by
// calped's fixed-point reference kernel or by a rounding of its float result to calped's
// format. Prints, per variant, the orientation channels' mean |diff| as % of their mean
// against the toolbox's level (../shared/reference/dollar-toolbox-pets/AcfCaltech+Detector).
// "This CPU's" reciprocals are the x86 instructions of the machine it runs on: the reference
// came from an AMD EPYC (family 26), where they reproduce it (docs/parity.md). x86 only.
//   caltech_precision [--frame PNG] [--shared DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <xmmintrin.h>

#include "kernels.h"
#include "test_data.h"

using namespace calped;
using namespace calped::kernels;

namespace {

// Which approximate reciprocals the emulated toolbox sees: Intel's rule (the INRIA
// reference's CPU), this CPU's own rcpps / rsqrtps, or exact division and square root.
enum class Approx { Intel, Hardware, Exact };
Approx gApprox = Approx::Intel;
// Per stage (colour, gradient, normalisation) when set: which approximation it sees.
Approx gStageApprox[3];
bool gPerStage = false;
int gStage = 0;

float intelRcpRule(float vf);
float intelRsqrtRule(float vf);

float toolboxRcp(float v)
{
	const Approx gApprox = gPerStage ? gStageApprox[gStage] : ::gApprox;
	if (gApprox == Approx::Hardware)
		return _mm_cvtss_f32(_mm_rcp_ss(_mm_set_ss(v)));
	if (gApprox == Approx::Exact)
		return 1.0f / v;
	return intelRcpRule(v);
}

float toolboxRsqrt(float v)
{
	const Approx gApprox = gPerStage ? gStageApprox[gStage] : ::gApprox;
	if (gApprox == Approx::Hardware)
		return _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(v)));
	if (gApprox == Approx::Exact)
		return v == 0 ? INFINITY : 1.0f / std::sqrt(v);
	return intelRsqrtRule(v);
}

// Intel's rcpps and rsqrtps (the rule of lib/kernels/tables.cpp), in float.
float intelRcpRule(float vf)
{
	int e;
	const double f = std::frexp(double(vf), &e);
	const double cell = std::floor(f * 4096.0) - 2048.0;
	const double mid = 1.0 + (cell + 0.5) / 2048.0;
	const double r = std::round(2.0 / mid * 4096.0) / 4096.0;
	return float(std::ldexp(r, -e));
}

float intelRsqrtRule(float vf)
{
	if (vf == 0)
		return INFINITY;
	int e;
	const double f = std::frexp(double(vf), &e);
	const double cell = std::floor(f * 2048.0) - 1024.0; // top 10 fraction bits of 2f
	// v = 2f * 2^ee: an odd power of two moves one 2 into the mantissa (floor division).
	const int ee = e - 1;
	const int halfExp = ee >= 0 ? ee / 2 : -((-ee + 1) / 2);
	double mid = 1.0 + (cell + 0.5) / 1024.0;
	if (ee - 2 * halfExp != 0)
		mid *= 2.0;
	const double r = std::round(2.0 / std::sqrt(mid) * 4096.0) / 4096.0;
	return float(std::ldexp(r, -halfExp - 1));
}

struct Img {
	int w = 0, h = 0;
	std::vector<float> v;
	float &at(int x, int y) { return v[size_t(y) * w + x]; }
	float at(int x, int y) const { return v[size_t(y) * w + x]; }
	void init(int width, int height)
	{
		w = width;
		h = height;
		v.assign(size_t(w) * h, 0.f);
	}
};

const float kPi = 3.14159265f;

const int kOrients = 6;

// ---- colour -------------------------------------------------------------------------------
void luvFloat(const test::RgbImage &im, Img luv[3])
{
	gStage = 0;
	const float nrm = 1.0f / 255;
	const float mr[3] = { 0.430574f * nrm, 0.222015f * nrm, 0.020183f * nrm };
	const float mg[3] = { 0.341550f * nrm, 0.706655f * nrm, 0.129553f * nrm };
	const float mb[3] = { 0.178325f * nrm, 0.071330f * nrm, 0.939180f * nrm };
	const float y0 = float((6.0 / 29) * (6.0 / 29) * (6.0 / 29));
	const float a = float((29.0 / 3) * (29.0 / 3) * (29.0 / 3));
	const float un = 0.197833f, vn = 0.468331f, maxi = 1.0f / 270;
	const float minu = -88 * maxi, minv = -134 * maxi;
	float lTable[1064];
	for (int i = 0; i < 1025; i++) {
		const float y = float(i / 1024.0);
		const float l = y > y0 ? 116 * float(std::pow(double(y), 1.0 / 3.0)) - 16 : y * a;
		lTable[i] = l * maxi;
	}
	for (int i = 1025; i < 1064; i++)
		lTable[i] = lTable[i - 1];
	for (int c = 0; c < 3; c++)
		luv[c].init(im.width, im.height);
	const float cun = 13 * un, cvn = 13 * vn;
	for (int y = 0; y < im.height; y++)
		for (int x = 0; x < im.width; x++) {
			const uint8_t *p = &im.pixels[(size_t(y) * im.width + x) * 3];
			const float r = p[0], g = p[1], b = p[2];
			const float X = r * mr[0] + g * mg[0] + b * mb[0];
			const float Y = r * mr[1] + g * mg[1] + b * mb[1];
			const float Z = r * mr[2] + g * mg[2] + b * mb[2];
			const float z = toolboxRcp(X + (1e-35f + (15.0f * Y + 3.0f * Z)));
			const float l = lTable[int(1024.0f * Y)];
			luv[0].at(x, y) = l;
			luv[1].at(x, y) = l * (52.0f * X * z - cun) - minu;
			luv[2].at(x, y) = l * (117.0f * Y * z - cvn) - minv;
		}
}

void luvFixed(const test::RgbImage &im, Img luv[3], RcpRule rule = RcpRule::Intel)
{
	LuvTables t;
	buildLuvTables(t, rule);
	std::vector<uint16_t> p[3];
	for (auto &q : p)
		q.resize(size_t(im.width) * im.height);
	rgbToLuv_ref(t, im.pixels.data(), 3 * im.width, im.width, im.height, p[0].data(), p[1].data(),
		     p[2].data(), im.width);
	for (int c = 0; c < 3; c++) {
		luv[c].init(im.width, im.height);
		for (size_t i = 0; i < p[c].size(); i++)
			luv[c].v[i] = p[c][i] / 65536.0f;
	}
}

// ---- gradient: magnitude and orientation in bins (o = theta * nOrients / pi) --------------
void gradFloat(const Img luv[3], Img &M, Img &O)
{
	gStage = 1;
	const int w = luv[0].w, h = luv[0].h;
	M.init(w, h);
	O.init(w, h);
	static float acost[20001];
	for (int i = -10000; i < 10000; i++) {
		float v = float(std::acos(i / 10000.0f));
		if (i < 1000 && v > kPi - 1e-6f)
			v = kPi - 1e-6f;
		acost[i + 10000] = v;
	}
	acost[20000] = 0;
	const float oMult = float(kOrients) / kPi;
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			float gx = 0, gy = 0, m2 = 0;
			for (int c = 0; c < 3; c++) {
				const Img &I = luv[c];
				const float cx = x == 0 ? I.at(1, y) - I.at(0, y)
					       : x == w - 1 ? I.at(w - 1, y) - I.at(w - 2, y)
							    : (I.at(x + 1, y) - I.at(x - 1, y)) * 0.5f;
				const float cy = y == 0 ? I.at(x, 1) - I.at(x, 0)
					       : y == h - 1 ? I.at(x, h - 1) - I.at(x, h - 2)
							    : (I.at(x, y + 1) - I.at(x, y - 1)) * 0.5f;
				const float cm2 = cx * cx + cy * cy;
				if (c == 0 || cm2 > m2) {
					m2 = cm2;
					gx = cx;
					gy = cy;
				}
			}
			const float r = std::min(toolboxRsqrt(m2), 1e10f);
			M.at(x, y) = toolboxRcp(r);
			float cs = gx * r * 10000.0f;
			if (std::signbit(gy))
				cs = -cs;
			O.at(x, y) = acost[int(cs) + 10000] * oMult;
		}
}

uint16_t toQ(float v, int q)
{
	const double s = std::round(double(v) * (1 << q));
	return uint16_t(std::clamp(s, 0.0, 65535.0));
}

void gradFixed(const Img luv[3], Img &M, Img &O)
{
	const int w = luv[0].w, h = luv[0].h;
	GradientTables t;
	buildGradientTables(t, kOrients, 5, 0.005);
	std::vector<uint16_t> p[3], mag(size_t(w) * h), ori(size_t(w) * h);
	const uint16_t *planes[3];
	for (int c = 0; c < 3; c++) {
		p[c].resize(size_t(w) * h);
		for (size_t i = 0; i < p[c].size(); i++)
			p[c][i] = toQ(luv[c].v[i], kLuvQ);
		planes[c] = p[c].data();
	}
	std::vector<int32_t> scratch(4 * size_t(w) + 16);
	gradMagOrient_ref(t, planes, w, w, h, mag.data(), ori.data(), w, scratch.data());
	M.init(w, h);
	O.init(w, h);
	for (size_t i = 0; i < mag.size(); i++) {
		M.v[i] = mag[i] / 65536.0f;
		O.v[i] = ori[i] / float(1 << kOrientQ);
	}
}

// ---- normalisation: M / (convTri(M, 5) + 0.005) -------------------------------------------
void normFloat(Img &M)
{
	gStage = 2;
	const int w = M.w, h = M.h, r = 5;
	// Triangle weights 1..r+1..1 with symmetric borders, in double.
	auto sym = [](int i, int n) { return i < 0 ? -i - 1 : (i >= n ? 2 * n - i - 1 : i); };
	Img T;
	T.init(w, h);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			double s = 0;
			for (int d = -r; d <= r; d++)
				s += (r + 1 - std::abs(d)) * double(M.at(sym(x + d, w), y));
			T.at(x, y) = float(s / ((r + 1) * (r + 1)));
		}
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			double s = 0;
			for (int d = -r; d <= r; d++)
				s += (r + 1 - std::abs(d)) * double(T.at(x, sym(y + d, h)));
			const float S = float(s / ((r + 1) * (r + 1)));
			M.at(x, y) = M.at(x, y) * toolboxRcp(S + 0.005f);
		}
}

void normFixed(Img &M)
{
	const int w = M.w, h = M.h;
	GradientTables t;
	buildGradientTables(t, kOrients, 5, 0.005);
	std::vector<uint16_t> m(size_t(w) * h);
	for (size_t i = 0; i < m.size(); i++)
		m[i] = toQ(M.v[i], kLuvQ);
	std::vector<uint32_t> sum(size_t(w) * h), scratch(triSumScratchSize(w, h, 5));
	triSumR_ref(m.data(), w, sum.data(), w, w, h, 5, scratch.data());
	normalizeMag_ref(t, m.data(), w, sum.data(), w, w, h);
	for (size_t i = 0; i < m.size(); i++)
		M.v[i] = m[i] / float(kOne);
}

// ---- gradHist, bin 2, softBin 1 -----------------------------------------------------------
// The toolbox's trilinear binning: pixel x sits at (x + .5) / 2 - .5 in cell units.
void histFloat(const Img &M, const Img &O, Img H[kOrients])
{
	const int w = M.w, h = M.h, wb = w / 2, hb = h / 2;
	for (int o = 0; o < kOrients; o++)
		H[o].init(wb, hb);
	for (int y = 0; y < 2 * hb; y++)
		for (int x = 0; x < 2 * wb; x++) {
			const float o = O.at(x, y);
			int o0 = int(o);
			const float od = o - float(o0);
			if (o0 >= kOrients)
				o0 = 0;
			const int o1 = o0 + 1 >= kOrients ? 0 : o0 + 1;
			const float m = M.at(x, y) * 0.25f;
			const float m1 = od * m, m0 = m - m1;
			const float xb = (x + 0.5f) * 0.5f - 0.5f, yb = (y + 0.5f) * 0.5f - 0.5f;
			const int xb0 = int(std::floor(xb)), yb0 = int(std::floor(yb));
			const float xd = xb - xb0, yd = yb - yb0;
			for (int j = 0; j < 2; j++)
				for (int i = 0; i < 2; i++) {
					const int cx = xb0 + i, cy = yb0 + j;
					if (cx < 0 || cx >= wb || cy < 0 || cy >= hb)
						continue;
					const float wgt = (i ? xd : 1 - xd) * (j ? yd : 1 - yd);
					H[o0].at(cx, cy) += wgt * m0;
					H[o1].at(cx, cy) += wgt * m1;
				}
		}
	for (int o = 0; o < kOrients; o++)
		for (int cy = 0; cy < hb; cy++)
			for (int cx = 0; cx < wb; cx++) {
				float f = 1;
				if (cx == 0 || cx == wb - 1)
					f *= 8.f / 7.f;
				if (cy == 0 || cy == hb - 1)
					f *= 8.f / 7.f;
				H[o].at(cx, cy) *= f;
			}
}

void histFixed(const Img &M, const Img &O, Img H[kOrients])
{
	const int w = M.w, h = M.h, wb = w / 2, hb = h / 2;
	std::vector<uint16_t> m(size_t(w) * h), o(size_t(w) * h);
	for (size_t i = 0; i < m.size(); i++) {
		m[i] = toQ(M.v[i], kQ);
		int q = int(std::lround(O.v[i] * (1 << kOrientQ)));
		if (q >= (kOrients << kOrientQ))
			q = (kOrients << kOrientQ) - 1;
		o[i] = uint16_t(q);
	}
	std::vector<uint16_t> planes[kOrients];
	uint16_t *hist[kOrients];
	for (int k = 0; k < kOrients; k++) {
		planes[k].resize(size_t(wb) * hb);
		hist[k] = planes[k].data();
	}
	std::vector<uint32_t> scratch(2 * kOrients * (size_t(w) + 4));
	gradHist2_ref(m.data(), o.data(), w, w, h, kOrients, true, true, hist, wb, scratch.data());
	for (int k = 0; k < kOrients; k++) {
		H[k].init(wb, hb);
		for (size_t i = 0; i < planes[k].size(); i++)
			H[k].v[i] = planes[k][i] / float(kOne);
	}
}

// ---- pyramid smoothing ([1 2 1]/4, replicated borders) and the comparison ----------------
void smooth(Img &C)
{
	Img T;
	T.init(C.w, C.h);
	for (int y = 0; y < C.h; y++)
		for (int x = 0; x < C.w; x++)
			T.at(x, y) = (C.at(std::max(x - 1, 0), y) + 2 * C.at(x, y) +
				      C.at(std::min(x + 1, C.w - 1), y)) * 0.25f;
	for (int y = 0; y < C.h; y++)
		for (int x = 0; x < C.w; x++)
			C.at(x, y) = (T.at(x, std::max(y - 1, 0)) + 2 * T.at(x, y) +
				      T.at(x, std::min(y + 1, C.h - 1))) * 0.25f;
}

// Mean |diff| / mean of each orientation channel of the padded level (pads: 4 rows,
// 3 columns of zeros), against the toolbox's level 1 ([h w c] column-major).
void report(const char *name, Img H[kOrients], const std::vector<float> &ref, int first = 4,
	    int count = kOrients, bool replicate = false)
{
	const int ph = H[0].h + 8, pw = H[0].w + 6;
	std::printf("%-44s", name);
	double worst = 0, sum = 0;
	for (int o = 0; o < count; o++) {
		Img C = H[o];
		smooth(C);
		std::vector<float> ours(size_t(ph) * pw, 0.f), theirs(size_t(ph) * pw);
		for (int y = 0; y < ph; y++)
			for (int x = 0; x < pw; x++) {
				const int cy = y - 4, cx = x - 3;
				if (cy >= 0 && cy < C.h && cx >= 0 && cx < C.w)
					ours[size_t(y) * pw + x] = C.at(cx, cy);
				else if (replicate)
					ours[size_t(y) * pw + x] = C.at(std::clamp(cx, 0, C.w - 1),
									std::clamp(cy, 0, C.h - 1));
				theirs[size_t(y) * pw + x] =
					ref[y + size_t(ph) * x + size_t(ph) * pw * (first + o)];
			}
		const test::DiffStats d = test::compare(ours.data(), theirs.data(), ours.size());
		const double pct = 100 * d.meanAbs / d.meanA;
		if (std::getenv("CALTECH_PRECISION_DEBUG")) {
			double so = 0, st = 0, inner = 0, innerMean = 0;
			for (size_t i = 0; i < ours.size(); i++) {
				so += ours[i];
				st += theirs[i];
				const int y = int(i / pw), x = int(i % pw);
				if (y >= 6 && y < ph - 6 && x >= 5 && x < pw - 5) {
					inner += std::fabs(ours[i] - theirs[i]);
					innerMean += ours[i];
				}
			}
			std::printf("\n   o%d sum ratio %.5f interior %.3f%%", o, st / so, 100 * inner / innerMean);
		}
		std::printf(" %5.3f", pct);
		worst = std::max(worst, pct);
		sum += pct;
	}
	std::printf("  | mean %.3f worst %.3f\n", sum / count, worst);
}

Img shrink2(const Img &I)
{
	Img S;
	S.init(I.w / 2, I.h / 2);
	for (int y = 0; y < S.h; y++)
		for (int x = 0; x < S.w; x++)
			S.at(x, y) = (I.at(2 * x, 2 * y) + I.at(2 * x + 1, 2 * y) + I.at(2 * x, 2 * y + 1) +
				      I.at(2 * x + 1, 2 * y + 1)) * 0.25f;
	return S;
}

} // namespace

int main(int argc, char **argv)
{
	std::string framePath, shared;
	for (int i = 1; i + 1 < argc; i += 2) {
		const std::string a = argv[i];
		if (a == "--frame")
			framePath = argv[i + 1];
		else if (a == "--shared")
			shared = argv[i + 1];
	}
	if (framePath.empty())
		framePath = test::petsFrame(1);
	if (shared.empty())
		shared = test::sharedDir();
	test::RgbImage img;
	if (framePath.empty() || !test::loadRgb(framePath, img)) {
		std::fprintf(stderr, "caltech_precision: cannot read PETS frame 1 (scripts/fetch-pets.sh)\n");
		return 1;
	}
	const std::vector<float> ref =
		test::readFloats(shared + "/reference/dollar-toolbox-pets/AcfCaltech+Detector/pyr_frame1_levels1-2.bin");
	if (ref.size() < size_t(296) * 390 * 10) {
		std::fprintf(stderr, "caltech_precision: no toolbox level in %s\n", shared.c_str());
		return 1;
	}
	// Channels are computed on the image cropped to a multiple of shrink (576 x 768 already is).
	std::printf("%-44s %5s %5s %5s %5s %5s %5s\n", "orientation channels, mean |diff| % of mean",
		    "o0", "o1", "o2", "o3", "o4", "o5");

	Img luvF[3], luvC[3], luvQ[3];
	luvFloat(img, luvF);
	luvFixed(img, luvC);
	for (int c = 0; c < 3; c++) {
		luvQ[c] = luvF[c];
		for (float &v : luvQ[c].v)
			v = toQ(v, kLuvQ) / 65536.0f;
	}

	enum Stage { kLuv, kGrad, kNorm, kHist };
	// fixedMask: which stages run calped's kernel; roundLuv: float LUV rounded to Q16.
	auto run = [&](const char *name, unsigned fixedMask, bool roundLuv, bool roundMag,
		       bool roundNorm, bool roundOrient) {
		const Img *luv = (fixedMask & (1u << kLuv)) ? luvC : (roundLuv ? luvQ : luvF);
		Img M, O;
		if (fixedMask & (1u << kGrad))
			gradFixed(luv, M, O);
		else
			gradFloat(luv, M, O);
		if (roundMag)
			for (float &v : M.v)
				v = toQ(v, kLuvQ) / 65536.0f;
		if (fixedMask & (1u << kNorm))
			normFixed(M);
		else
			normFloat(M);
		if (roundNorm)
			for (float &v : M.v)
				v = toQ(v, kQ) / float(kOne);
		if (roundOrient)
			for (float &v : O.v)
				v = std::lround(v * (1 << kOrientQ)) / float(1 << kOrientQ);
		Img H[kOrients];
		if (fixedMask & (1u << kHist))
			histFixed(M, O, H);
		else
			histFloat(M, O, H);
		report(name, H, ref);
	};
	for (Approx a : { Approx::Exact, Approx::Hardware, Approx::Intel }) {
		gApprox = a;
		std::printf("approximate reciprocals: %s\n", a == Approx::Intel ? "Intel's rule" : a == Approx::Hardware ? "this CPU's rcpps/rsqrtps" : "none (exact)");
		luvFloat(img, luvF);
		Img C[3] = { shrink2(luvF[0]), shrink2(luvF[1]), shrink2(luvF[2]) };
		report("float emulation: colour channels", C, ref, 0, 3, true);
		Img M, O;
		gradFloat(luvF, M, O);
		normFloat(M);
		Img Ms[1] = { shrink2(M) };
		report("float emulation: magnitude channel", Ms, ref, 3, 1);
		run("float emulation: orientation channels", 0, false, false, false, false);
	}
	gApprox = Approx::Hardware;
	luvFloat(img, luvF);
	for (int c = 0; c < 3; c++) {
		luvQ[c] = luvF[c];
		for (float &v : luvQ[c].v)
			v = toQ(v, kLuvQ) / 65536.0f;
	}
	std::printf("this CPU's reciprocals in some stages only (others Intel's):\n");
	const char *stageNames[3] = { "colour", "gradient", "normalisation" };
	for (unsigned mask = 1; mask < 7; mask++) {
		gPerStage = true;
		std::string label = "  this CPU's in:";
		for (int st = 0; st < 3; st++) {
			gStageApprox[st] = (mask >> st) & 1 ? Approx::Hardware : Approx::Intel;
			if ((mask >> st) & 1)
				label += std::string(" ") + stageNames[st];
		}
		luvFloat(img, luvF);
		run(label.c_str(), 0, false, false, false, false);
	}
	gPerStage = false;
	luvFloat(img, luvF);
	std::printf("this CPU's reciprocals, one of calped's roundings at a time:\n");
	run("  LUV rounded to Q16", 0, true, false, false, false);
	run("  magnitude rounded to Q16", 0, false, true, false, false);
	run("  normalised magnitude rounded to Q14", 0, false, false, true, false);
	run("  orientation rounded to 1/1024 bin", 0, false, false, false, true);
	run("  calped histograms (gradHist2)", 1u << kHist, false, false, false, false);
	run("  all of these", 1u << kHist, true, true, true, true);
	gApprox = Approx::Intel;
	luvFloat(img, luvF);
	for (int c = 0; c < 3; c++) {
		luvQ[c] = luvF[c];
		for (float &v : luvQ[c].v)
			v = toQ(v, kLuvQ) / 65536.0f;
	}
	std::printf("Intel's rule, one stage at a time rounded or replaced by calped's kernel:\n");
	run("float emulation of the toolbox", 0, false, false, false, false);
	run("  LUV rounded to Q16", 0, true, false, false, false);
	run("  magnitude rounded to Q16", 0, false, true, false, false);
	run("  normalised magnitude rounded to Q14", 0, false, false, true, false);
	run("  orientation rounded to 1/1024 bin", 0, false, false, false, true);
	run("  calped LUV (rgbToLuv)", 1u << kLuv, false, false, false, false);
	run("  calped gradient (gradMagOrient, Q16 in)", 1u << kGrad, false, false, false, false);
	run("  calped normalisation (triSum, normalizeMag)", 1u << kNorm, false, false, false, false);
	run("  calped histograms (gradHist2)", 1u << kHist, false, false, false, false);
	run("calped LUV + gradient", (1u << kLuv) | (1u << kGrad), false, false, false, false);
	run("calped LUV + gradient + normalisation",
	    (1u << kLuv) | (1u << kGrad) | (1u << kNorm), false, false, false, false);
	run("calped, every stage", 15u, false, false, false, false);
	luvFixed(img, luvC, RcpRule::AmdEpyc);
	run("calped, every stage, AMD EPYC colour rcpps", 15u, false, false, false, false);
	return 0;
}
