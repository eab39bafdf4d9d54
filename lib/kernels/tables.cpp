// SPDX-License-Identifier: BSD-2-Clause
// Lookup tables for the kernels, built once at setup (never on the per-frame path).
#include "kernels.h"
#include "opt/ldcf_body.h"

#include <algorithm>
#include <cmath>

namespace calped {
namespace kernels {

namespace {

int32_t roundToInt(double v) { return static_cast<int32_t>(std::lround(v)); }

// The toolbox's SSE code divides with the approximate reciprocal instructions (rcpps,
// rsqrtps), whose results on the Intel CPU that made the reference follow a simple rule
// (docs/channels.md): the input's mantissa is cut to its top 11 (reciprocal) or 10
// (reciprocal square root) fraction bits, the function is taken at the middle of that
// interval, and the result is rounded to nearest at 12 fraction bits. Reproducing them,
// rather than dividing exactly, is what brings the orientation channels to the toolbox's.

// Intel's rcpps of v > 0, exactly (a double holds it).
double intelRcp(double v)
{
	int e;
	const double f = std::frexp(v, &e); // v = f * 2^e, f in [0.5, 1)
	const double cell = std::floor(f * 4096.0) - 2048.0; // top 11 fraction bits of 2f
	const double mid = 1.0 + (cell + 0.5) / 2048.0;     // 2f's interval midpoint, in [1, 2)
	const double r = std::round(2.0 / mid * 4096.0) / 4096.0; // in (1, 2), 12 fraction bits
	return std::ldexp(r, -e); // 1 / v = (2 / 2f) * 2^-e
}

// Intel's rsqrtps of v > 0, exactly.
double intelRsqrt(double v)
{
	int e;
	const double f = std::frexp(v, &e); // v = 2f * 2^(e-1), 2f in [1, 2)
	const double cell = std::floor(f * 2048.0) - 1024.0; // top 10 fraction bits of 2f
	double mid = 1.0 + (cell + 0.5) / 1024.0;
	int halfExp = (e - 1) / 2;
	if ((e - 1) % 2 != 0) { // odd power of two: take one 2 into the mantissa
		mid *= 2.0;
		halfExp = (e - 2) / 2;
	}
	// 1 / sqrt(mid) is in (0.5, 1]: normalise to (1, 2] before rounding 12 fraction bits.
	const double r = std::round(2.0 / std::sqrt(mid) * 4096.0) / 4096.0;
	return std::ldexp(r, -halfExp - 1);
}

// AMD's rcpps (bench/amd_rcp_table.cpp), as corrections in {-1, 0, 1} units of 2^-12 to
// the midpoint rule over cells of 12 fraction bits.
const uint32_t kAmdRcpDelta[256] = {
#include "amd_rcp_table.inc"
};

// rcpps of v > 0 by `rule`, exactly (a double holds it).
double ruleRcp(double v, RcpRule rule)
{
	if (rule == RcpRule::Intel)
		return intelRcp(v);
	int e;
	const double f = std::frexp(v, &e);
	const int cell = int(std::floor(f * 8192.0)) - 4096; // top 12 fraction bits of 2f
	const double mid = 1.0 + (cell + 0.5) / 4096.0;
	const int delta = int((kAmdRcpDelta[cell / 16] >> (2 * (cell % 16))) & 3u) - 1;
	const double r = (std::round(2.0 / mid * 4096.0) + delta) / 4096.0;
	return std::ldexp(r, -e);
}

} // namespace

void buildLuvTables(LuvTables &t, RcpRule rule)
{
	// The toolbox's sRGB -> XYZ matrix (rgbConvertMex), applied to 8-bit values / 255.
	const double mr[3] = { 0.430574, 0.222015, 0.020183 };
	const double mg[3] = { 0.341550, 0.706655, 0.129553 };
	const double mb[3] = { 0.178325, 0.071330, 0.939180 };
	const double q28 = (1 << 28) / 255.0;
	int32_t *rows[3] = { t.cx, t.cy, t.cz };
	for (int j = 0; j < 3; j++) {
		rows[j][0] = roundToInt(mr[j] * q28);
		rows[j][1] = roundToInt(mg[j] * q28);
		rows[j][2] = roundToInt(mb[j] * q28);
	}

	// L / 270 for y = i / 1024, CIE lightness with the linear toe below (6/29)^3.
	const double y0 = std::pow(6.0 / 29.0, 3.0);
	const double a = std::pow(29.0 / 3.0, 3.0);
	const double maxi = 1.0 / 270.0;
	for (int i = 0; i < 1025; i++) {
		const double y = i / 1024.0;
		const double l = y > y0 ? 116.0 * std::cbrt(y) - 16.0 : y * a;
		t.l[i] = static_cast<uint16_t>(roundToInt(l * maxi * (1 << kLuvQ)));
	}
	for (int i = 1025; i < 1025 + 39; i++)
		t.l[i] = t.l[1024];

	for (int m = 0; m < 4096; m++) // exact: rcpps keeps 12 fraction bits, 2^28 / m has 15
		t.rcp[m] = static_cast<uint32_t>(std::lround(ruleRcp(4096 + m, rule) * (1 << 28)));

	const double one = 1 << kLuvQ, ratioOne = 1 << kLuvRatioQ;
	t.un13 = roundToInt(13.0 * 0.197833 * ratioOne);
	t.vn13 = roundToInt(13.0 * 0.468331 * ratioOne);
	t.minu = roundToInt(-88.0 * maxi * one);
	t.minv = roundToInt(-134.0 * maxi * one);
}

void buildGradientTables(GradientTables &t, int nOrients, int normRad, double normConst)
{
	// The toolbox's magnitude is rcpps(rsqrtps(M2)) and its cosine Gx * rsqrtps(M2). Both
	// depend on M2 only through its top 10 fraction bits and the parity of its exponent,
	// so the 12-bit index m (normalizeEven: m2 = m * 4^j) loses nothing, and scaling by 4^j
	// scales the results exactly.
	t.sqrtQ8[0] = 0;
	t.rsqrtQ20[0] = 0;
	for (int m = 1; m < 4096; m++) {
		const double rs = intelRsqrt(m);
		t.sqrtQ8[m] = static_cast<uint16_t>(std::lround(intelRcp(rs) * 256.0));
		t.rsqrtQ20[m] = static_cast<uint32_t>(std::lround(rs * (1 << 20))); // exact
	}
	for (int m = 0; m < 4096; m++)
		t.roots[m] = t.rsqrtQ20[m] | uint64_t(t.sqrtQ8[m]) << 32;

	// The toolbox's acos table in single precision (acos(i / 10000), capped at pi - 1e-6),
	// turned into o = theta * nOrients / pi as its gradQuantize computes it (in float),
	// then rounded (not truncated, so the split between neighbouring bins is unbiased) to
	// kOrientQ fraction bits and kept below nOrients.
	t.nOrients = nOrients;
	const int oMax = (nOrients << kOrientQ) - 1;
	const float piF = 3.14159265f, oMult = float(nOrients) / piF;
	for (int c = -kCosSteps; c <= kCosSteps; c++) {
		// acos in double (the same on every platform), of the toolbox's float argument.
		const float theta = std::min(float(std::acos(double(c / float(kCosSteps)))), piF - 1e-6f);
		const int o = static_cast<int>(std::lround(double(theta * oMult) * (1 << kOrientQ)));
		t.fromCos[c + kCosSteps] = static_cast<uint16_t>(std::clamp(o, 0, oMax));
	}

	const double weightSum = std::pow(normRad + 1.0, 4.0);
	for (int m = 0; m < 2048; m++)
		t.normRcp[m] = static_cast<uint32_t>(
			std::lround(weightSum * 65536.0 * intelRcp(2048 + m)));
	t.normConst = static_cast<uint32_t>(std::lround(normConst * (1 << kLuvQ) * weightSum));
}

} // namespace kernels
} // namespace calped

namespace calped {
namespace kernels {

bool buildResampleTaps(int n, int m, double gain, ResampleTap *taps)
{
	// Single precision on purpose: these are the toolbox's own float computations.
	const float s = float(m) / float(n), sInv = 1 / s;
	const float wt0 = 1e-3f * s;
	for (int o = 0; o < m; o++) {
		ResampleTap &t = taps[o];
		float w[kMaxTaps + 2];
		int first = 0, count = 0;
		if (n > m) {
			// Shrinking: area weights of the source samples the output cell covers.
			const float ya0f = o * sInv, ya1f = ya0f + sInv;
			const int ya0 = int(std::ceil(ya0f)), ya1 = int(ya1f);
			float sum = 0;
			for (int ya = ya0 - 1; ya < ya1 + 1; ya++) {
				float wt = s;
				if (ya == ya0 - 1)
					wt = (ya0 - ya0f) * s;
				else if (ya == ya1)
					wt = (ya1f - ya1) * s;
				if (!(wt > wt0 && ya >= 0 && ya < n))
					continue;
				if (count == 0)
					first = ya;
				if (count == kMaxTaps || ya != first + count)
					return false;
				w[count++] = wt;
				sum += wt;
			}
			if (sum > 1)
				for (int j = 0; j < count; j++)
					w[j] /= sum;
		} else {
			// Enlarging (or copying): bilinear between the two nearest source samples,
			// pixel centres aligned, clamped at the borders.
			const float yaf = (0.5f + o) * sInv - 0.5f;
			int ya = int(std::floor(yaf));
			float wt = 1;
			if (ya >= 0 && ya < n - 1)
				wt = 1 - (yaf - ya);
			if (ya < 0)
				ya = 0;
			if (ya >= n - 1)
				ya = n - 1;
			first = ya;
			w[count++] = wt;
			if (wt < 1)
				w[count++] = 1 - wt;
		}
		// Quantise to Q14 keeping the sum exact (flat input stays flat).
		double total = 0;
		int32_t qsum = 0, big = 0;
		for (int j = 0; j < count; j++) {
			total += w[j];
			t.weight[j] = roundToInt(w[j] * gain * kOne);
			qsum += t.weight[j];
			if (t.weight[j] > t.weight[big])
				big = j;
		}
		if (count > 0)
			t.weight[big] += roundToInt(total * gain * kOne) - qsum;
		t.first = first;
		t.count = count;
	}
	return true;
}

bool packLdcfCellFilter(const int32_t *weights, int size, int16_t *packed)
{
	constexpr int kSize = 5, kColumns = 4, kLanes = 8;
	static_assert(kLdcfPackedCount == kSize * kColumns * kLanes, "the packed layout");
	if (!ldcf::vectorizable(weights, size))
		return false;
	for (int a = 0; a < kSize; a++)
		for (int j = 0; j < kColumns; j++) {
			int16_t *lanes = packed + (a * kColumns + j) * kLanes;
			for (int lane = 0; lane < kLanes; lane++) {
				const int b = j + 4 - lane; // the tap that meets this lane's sample
				lanes[lane] = b >= 0 && b < kSize ? int16_t(weights[a * kSize + b]) : 0;
			}
		}
	return true;
}

} // namespace kernels
} // namespace calped
