// SPDX-License-Identifier: BSD-2-Clause
// Detector::detect on arbitrary frames: the input's first bytes choose one of a few
// configurations (resize in the pyramid or of the frame, NMS, a cascade threshold, static
// rejection, one or two threads), the pixel format (declared or not), the size (up to past the maximum), the
// stride (down to one byte short of a row) and the YUV encoding; the rest are the pixels.
// Every plane is allocated to exactly the bytes its size and stride give, so a read past
// a row, a plane or the last row is an ASan report. Detectors are made once per
// configuration and reused, so an input costs one small frame (fast enough for millions).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include <calped/detector.h>
#include <calped/model.h>

#include "fuzz_checks.h"

namespace {

using namespace calped;

constexpr int kMaxW = 96, kMaxH = 128; // above the INRIA window (41 x 100) at resize 1

// A valid model with the INRIA model's options and a few random depth-2 trees (a fixed
// generator: the same model in every run).
Model smallModel()
{
	Model m;
	m.name = "fuzz";
	m.nTrees = 16;
	m.nodesPerTree = 7;
	m.treeDepth = 2;
	uint32_t state = 12345;
	auto next = [&state] { return state = state * 1664525u + 1013904223u; };
	const uint32_t child[7] = { 1, 3, 5, 0, 0, 0, 0 };
	for (int t = 0; t < m.nTrees; t++)
		for (int k = 0; k < 7; k++) {
			m.fids.push_back(k < 3 ? next() % uint32_t(m.featureCount()) : 0);
			m.thrs.push_back(k < 3 ? int32_t(next() % 16385) : 0);
			m.child.push_back(child[k]);
			m.hs.push_back(k < 3 ? 0 : int32_t(next() % 65536) - 32768);
		}
	return m;
}

DetectorConfig configFor(int k)
{
	DetectorConfig c;
	c.maxWidth = kMaxW;
	c.maxHeight = kMaxH;
	c.maxCandidates = 64; // small: the overflow path is reached too
	switch (k & 3) {
	case 0: break;
	case 1: c.resize = 1.5; break;
	case 2: c.resize = 0.8; c.resizeAt = ResizeAt::Frame; break;
	case 3: c.resize = 1.25; c.resizeAt = ResizeAt::Frame; break;
	}
	c.nms = (k & 4) == 0;
	c.cascadeThreshold = (k & 8) ? -2.0f : __builtin_nanf("");
	if (k & 16) {
		StaticRejection s;
		s.warmupFrames = 2;
		c.staticRejection = s;
	}
	// Two threads: the work cut into segments over the pool at every odd size.
	c.threads = (k & 32) ? 2 : 1;
	return c;
}

constexpr int kConfigs = 64;

Detector *detectorFor(int k)
{
	static const Model model = smallModel();
	static std::unique_ptr<Detector> detectors[kConfigs];
	if (!detectors[k]) {
		const Status st = Detector::create(model, configFor(k), detectors[k]);
		if (!st.ok())
			fuzz::fail("every fuzz configuration is valid", st.message());
	}
	return detectors[k].get();
}

// Bytes of one row of a plane of the format (plane 0: the image's; 1, 2: chroma).
long rowBytes(PixelFormat f, int plane, int w)
{
	const long cw = (w + 1) / 2;
	switch (f) {
	case PixelFormat::RGB8:
	case PixelFormat::BGR8: return 3L * w;
	case PixelFormat::YUYV: return 4 * cw;
	case PixelFormat::NV12: return plane == 0 ? w : 2 * cw;
	case PixelFormat::YUV420: return plane == 0 ? w : cw;
	default: return w; // Gray8, Bayer
	}
}

int planeCount(PixelFormat f)
{
	return f == PixelFormat::NV12 ? 2 : f == PixelFormat::YUV420 ? 3 : 1;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size < 8)
		return 0;
	const int k = data[0] % kConfigs;
	const int formatValue = data[1] % 12; // 10 and 11 are not formats
	const int w = data[2] % (kMaxW + 9), h = (data[3] | (data[4] << 8)) % (kMaxH + 9);
	const int strideExtra = int(data[5] % 20) - 1; // -1: one byte short of a row
	const int yuv = data[6] % 5;                    // 4 is not an encoding
	const bool dropPlane = data[7] == 0xff;         // a null plane the format needs
	const uint8_t *pixels = data + 8;
	const size_t pixelBytes = size - 8;

	const auto format = static_cast<PixelFormat>(formatValue);
	const bool known = formatValue < 10;
	const int planes = known ? planeCount(format) : 1;
	std::vector<uint8_t> buffers[3];
	ImageView view;
	view.format = format;
	view.width = w;
	view.height = h;
	view.yuv = static_cast<YuvEncoding>(yuv);
	for (int p = 0; p < planes; p++) {
		const long row = known ? rowBytes(format, p, w) : 3L * w;
		const int rows = p == 0 ? h : (h + 1) / 2;
		const long stride = row + strideExtra;
		// Exactly the last row's bytes after the others' strides: nothing more to read.
		const long bytes = rows > 0 && stride > 0 ? stride * (rows - 1) + std::max(row, 0L) : 0;
		buffers[p].resize(size_t(bytes));
		for (size_t i = 0; i < buffers[p].size(); i++)
			buffers[p][i] = pixelBytes ? pixels[(i + 7919 * size_t(p)) % pixelBytes] : uint8_t(i);
		view.planes[p] = buffers[p].empty() ? nullptr : buffers[p].data();
		view.strides[p] = int(stride);
	}
	if (dropPlane)
		view.planes[planes - 1] = nullptr;

	Detector *det = detectorFor(k);
	Detections out;
	const Status st = det->detect(view, out);
	if (!st.ok()) {
		if (!fuzz::printableLine(st.message()) || std::strstr(st.message(), errorCodeName(st.code())) != st.message())
			fuzz::fail("an error message starts with its code's name on one printable line", st.message());
		if (out.count != 0)
			fuzz::fail("a failed detect() returns no detections", st.message());
		const bool sizeOk = w >= 1 && h >= 1 && w <= kMaxW && h <= kMaxH;
		if (known && sizeOk && strideExtra >= 0 && yuv < 4 && !dropPlane &&
		    st.code() != ErrorCode::ImageTooSmall)
			fuzz::fail("a well-formed frame within the maximum is detected (or too small)", st.message());
		return 0;
	}
	if (!known || w < 1 || h < 1 || w > kMaxW || h > kMaxH || strideExtra < 0 || dropPlane)
		fuzz::fail("a malformed frame is refused", "detect() succeeded");
	if (out.count < 0 || out.count > 64)
		fuzz::fail("detections within maxCandidates", "");
	for (const Detection &d : out)
		if (!std::isfinite(d.x) || !std::isfinite(d.y) || !(d.w > 0) || !(d.h > 0) || !std::isfinite(d.score))
			fuzz::fail("boxes are finite with a positive size", "");
	return 0;
}
