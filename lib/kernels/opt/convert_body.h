// SPDX-License-Identifier: BSD-2-Clause
// Scalar pieces shared by the optimised conversions (opt/ and the x86 tails): YUV with the
// chroma terms computed once per shared sample, and Bayer sites with fixed types.
#pragma once

#include "kernels.h"

namespace calped {
namespace kernels {
namespace {

inline uint8_t clamp255(int32_t v) { return uint8_t(v < 0 ? 0 : (v > 255 ? 255 : v)); }

// Chroma terms of one U, V pair, added to c.y * (Y - yOffset) + 128 before the shift.
struct Chroma {
	int32_t r, g, b;
};

inline Chroma chromaTerms(const YuvCoeffs &c, int u, int v)
{
	const int32_t d = u - 128, e = v - 128;
	return { c.rv * e, -c.gu * d - c.gv * e, c.bu * d };
}

inline void yuvPixel(const YuvCoeffs &c, const Chroma &k, int y, uint8_t *rgb)
{
	const int32_t luma = c.y * (y - c.yOffset) + 128;
	rgb[0] = clamp255((luma + k.r) >> 8);
	rgb[1] = clamp255((luma + k.g) >> 8);
	rgb[2] = clamp255((luma + k.b) >> 8);
}

// Pixels [x0, width) of a 4:2:0 row (x0 even).
inline void yuv420RowTail(const YuvCoeffs &c, const uint8_t *luma, const uint8_t *u,
			  const uint8_t *v, int step, int x0, int width, uint8_t *d)
{
	int x = x0;
	for (; x + 1 < width; x += 2) {
		const Chroma k = chromaTerms(c, u[(x / 2) * step], v[(x / 2) * step]);
		yuvPixel(c, k, luma[x], d + 3 * x);
		yuvPixel(c, k, luma[x + 1], d + 3 * x + 3);
	}
	if (x < width) // odd width: the last pixel has a chroma sample of its own
		yuvPixel(c, chromaTerms(c, u[(x / 2) * step], v[(x / 2) * step]), luma[x], d + 3 * x);
}

// Pixels [x0, width) of a YUYV row (x0 even).
inline void yuyvRowTail(const YuvCoeffs &c, const uint8_t *s, int x0, int width, uint8_t *d)
{
	int x = x0;
	for (; x + 1 < width; x += 2) {
		const uint8_t *q = s + 2 * x;
		const Chroma k = chromaTerms(c, q[1], q[3]);
		yuvPixel(c, k, q[0], d + 3 * x);
		yuvPixel(c, k, q[2], d + 3 * x + 3);
	}
	if (x < width) // odd width: the last pair has one pixel
		yuvPixel(c, chromaTerms(c, s[2 * x + 1], s[2 * x + 3]), s[2 * x], d + 3 * x);
}

// The four kinds of Bayer site (see bayerToRgb8_ref).
enum Site { RedSite, BlueSite, GreenInRedRow, GreenInBlueRow };

// Pixel at column x of row c, with row u above and row b below; l and r are the columns
// left and right of x (mirrored at the borders).
template <Site site>
inline void demosaic(const uint8_t *u, const uint8_t *c, const uint8_t *b, int l, int x, int r,
		     uint8_t *out)
{
	const int here = c[x];
	if (site == RedSite || site == BlueSite) {
		const int cross = (c[l] + c[r] + u[x] + b[x] + 2) >> 2;
		const int diagonal = (u[l] + u[r] + b[l] + b[r] + 2) >> 2;
		out[0] = uint8_t(site == RedSite ? here : diagonal);
		out[1] = uint8_t(cross);
		out[2] = uint8_t(site == RedSite ? diagonal : here);
	} else {
		const int across = (c[l] + c[r] + 1) >> 1;
		const int vertical = (u[x] + b[x] + 1) >> 1;
		out[0] = uint8_t(site == GreenInRedRow ? across : vertical);
		out[1] = uint8_t(here);
		out[2] = uint8_t(site == GreenInRedRow ? vertical : across);
	}
}

// Pixels [x0, w) of a row (x0 >= 1), the last one mirroring its right neighbour.
template <Site even, Site odd>
inline void demosaicTail(const uint8_t *u, const uint8_t *c, const uint8_t *b, int x0, int w,
			 uint8_t *d)
{
	for (int x = x0; x < w; x++) {
		const int l = x - 1, r = x + 1 < w ? x + 1 : w - 2;
		if (x & 1)
			demosaic<odd>(u, c, b, l, x, r, d + 3 * x);
		else
			demosaic<even>(u, c, b, l, x, r, d + 3 * x);
	}
}

} // namespace
} // namespace kernels
} // namespace calped
