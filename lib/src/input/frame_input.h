// SPDX-License-Identifier: BSD-2-Clause
// The detector's input stage: checks a camera frame of any pixel format and hands it on
// as interleaved RGB8 rows, a strip at a time (a small scratch converted per strip) or as
// one whole RGB8 image (for the input resize). RGB8 frames are never copied.
// docs/pixel-formats.md describes the formats and conversions.
#pragma once

#include <calped/image.h>
#include <calped/status.h>

#include <vector>

#include "kernels.h"

namespace calped {

// Planes, strides and sizes of an image in any format: ImageEmpty (no pixels),
// UnsupportedPixelFormat, InvalidArgument (stride or encoding) or ImageTooSmall (Bayer
// below 2x2), each message naming the format.
Status checkImageLayout(const ImageView &image);

class FrameInput
{
public:
	// Rows converted per strip: even, so 4:2:0 strips start on a chroma row.
	static constexpr int kStripRows = 8;

	// Buffers for frames up to maxWidth x maxHeight: the strip scratch, and with
	// wholeFrames a full-frame RGB8 buffer for wholeFrame().
	Status init(int maxWidth, int maxHeight, bool wholeFrames,
		    const kernels::ConvertKernels &k = kernels::bestConvertKernels());

	// Take a frame that passed checkImageLayout() and fits the maximum size.
	void begin(const ImageView &image);
	int width() const { return image_.width; }
	int height() const { return image_.height; }

	// How many rows one rows() call can deliver: the whole frame for RGB8, else kStripRows.
	int stripRows() const;
	// Rows [y0, y0 + count) as interleaved RGB8 (count <= stripRows()): the frame itself
	// for RGB8, otherwise converted into the strip scratch (valid until the next call).
	const uint8_t *rows(int y0, int count, ptrdiff_t &stride);
	// The same converted into the caller's scratch (kStripRows rows of the frame's width
	// in RGB8): threads may convert different strips of one frame at once.
	const uint8_t *rows(int y0, int count, ptrdiff_t &stride, uint8_t *scratch) const;
	// The whole frame as RGB8: the frame itself for RGB8, otherwise converted into the
	// full-frame buffer (needs init() with wholeFrames).
	const uint8_t *wholeFrame(ptrdiff_t &stride);

private:
	kernels::ConvertRowsFn converter() const;

	const kernels::ConvertKernels *k_ = nullptr;
	ImageView image_;
	kernels::RawFrame raw_;
	kernels::ConvertRowsFn convert_ = nullptr;
	int maxWidth_ = 0, maxHeight_ = 0;
	std::vector<uint8_t> strip_; // kStripRows rows of maxWidth RGB pixels
	std::vector<uint8_t> whole_; // maxWidth x maxHeight RGB pixels (wholeFrames only)
};

} // namespace calped
