// SPDX-License-Identifier: BSD-2-Clause
// Camera pixel formats -> RGB8, restructured for speed; bit-identical to ref/convert_ref.cpp.
// YUV: the chroma terms are computed once per pair of pixels sharing them. Bayer: rows
// are mirrored once per row and columns only at the two border pixels, and the interior
// goes two pixels (one 2x2-block column) at a time with the site types fixed per row.
#include "opt/convert_body.h"

namespace calped {
namespace kernels {

void yuv420ToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++)
		yuv420RowTail(f.yuv, f.planes[0] + y * f.strides[0], f.planes[1] + (y / 2) * f.strides[1],
			      f.planes[2] + (y / 2) * f.strides[2], f.chromaStep, 0, f.width,
			      dst + (y - y0) * dstStride);
}

void yuyvToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	for (int y = y0; y < y0 + rows; y++)
		yuyvRowTail(f.yuv, f.planes[0] + y * f.strides[0], 0, f.width, dst + (y - y0) * dstStride);
}

namespace {

template <Site even, Site odd>
void demosaicRow(const uint8_t *u, const uint8_t *c, const uint8_t *b, int w, uint8_t *d)
{
	// Column 0 mirrors its left neighbour to column 1; column w - 1 its right to w - 2.
	demosaic<even>(u, c, b, 1, 0, 1, d);
	int x = 1;
	for (; x + 1 < w - 1; x += 2) {
		demosaic<odd>(u, c, b, x - 1, x, x + 1, d + 3 * x);
		demosaic<even>(u, c, b, x, x + 1, x + 2, d + 3 * x + 3);
	}
	demosaicTail<even, odd>(u, c, b, x, w, d);
}

} // namespace

void bayerToRgb8_opt(const RawFrame &f, int y0, int rows, uint8_t *dst, ptrdiff_t dstStride)
{
	const int w = f.width, h = f.height;
	for (int y = y0; y < y0 + rows; y++) {
		const int above = y > 0 ? y - 1 : 1, below = y + 1 < h ? y + 1 : h - 2;
		const uint8_t *u = f.planes[0] + above * f.strides[0];
		const uint8_t *c = f.planes[0] + y * f.strides[0];
		const uint8_t *b = f.planes[0] + below * f.strides[0];
		uint8_t *d = dst + (y - y0) * dstStride;
		const bool redRow = (y & 1) == f.redY;
		// Site of the even columns, then of the odd ones.
		if (redRow && f.redX == 0)
			demosaicRow<RedSite, GreenInRedRow>(u, c, b, w, d);
		else if (redRow)
			demosaicRow<GreenInRedRow, RedSite>(u, c, b, w, d);
		else if (f.redX == 0)
			demosaicRow<GreenInBlueRow, BlueSite>(u, c, b, w, d);
		else
			demosaicRow<BlueSite, GreenInBlueRow>(u, c, b, w, d);
	}
}

} // namespace kernels
} // namespace calped
