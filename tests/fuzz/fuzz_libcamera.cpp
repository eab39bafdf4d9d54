// SPDX-License-Identifier: BSD-2-Clause
// What a libcamera stream answers, as the libcamera port checks it (ports/libcamera/
// frame_layout.h and checkPlanes in plane_mapping.h, no camera): a buffer's planes (fd,
// offset, length) against their memory, then the stream's format (fourcc and modifier),
// size and stride against those planes. The memory behind each fd is a heap block of
// exactly its size and planes point into it as mmap would, so an accepted frame is
// checked two ways: every row of every colour plane lies inside the plane it came from
// (checked explicitly, and each row is read, so ASan sees an overread), and the view has
// the stream's size and the format its fourcc maps to. A refusal is one printable line.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "fuzz_checks.h"
#include "fuzz_input.h"

#include "frame_layout.h"
#include "plane_mapping.h"

namespace {

using namespace calped;
using namespace calped::ports;

const uint32_t kFourccs[] = { kFourccNV12,   kFourccYUV420, kFourccYUYV,   kFourccRGB888,
			      kFourccBGR888, kFourccR8,     kFourccSRGGB8, kFourccSGRBG8,
			      kFourccSGBRG8, kFourccSBGGR8,
			      fourcc('N', 'V', '2', '1'), fourcc('X', 'R', '2', '4'),
			      fourcc('M', 'J', 'P', 'G'), fourcc('R', 'G', '1', '0') };
constexpr size_t kFourccCount = sizeof(kFourccs) / sizeof(kFourccs[0]);
constexpr size_t kMaxMemory = size_t(1) << 16; // per fd: inputs stay fast (frames up to 64 KiB)

// Fails unless every row of view plane `p` (rows of rowBytes, stride apart) is inside
// `from`; reads each row's first and last byte.
void checkRows(const ImageView &v, int p, int64_t rowBytes, int64_t rows, const MappedPlane &from)
{
	const uintptr_t b = reinterpret_cast<uintptr_t>(from.data), e = b + from.length;
	volatile uint8_t sink = 0;
	for (int64_t y = 0; y < rows; y++) {
		const uint8_t *row = v.planes[p] + y * v.strides[p];
		const uintptr_t r = reinterpret_cast<uintptr_t>(row);
		if (!v.planes[p] || v.strides[p] < rowBytes || r < b || r + uint64_t(rowBytes) > e)
			fuzz::fail("every row of an accepted frame lies in its plane", "");
		sink = sink + row[0] + row[rowBytes - 1];
	}
	(void)sink;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz::Input in(data, size);
	// The buffer: up to 4 fds with their memory, then up to 5 planes on them.
	const int fds = 1 + in.u8() % 4;
	std::unique_ptr<uint8_t[]> memory[4]; // exactly the fd's size: ASan sees past it
	int64_t memorySize[4];
	for (int f = 0; f < fds; f++) {
		memorySize[f] = int64_t(in.bits(3) % (kMaxMemory + 1));
		memory[f].reset(new uint8_t[size_t(memorySize[f])]);
	}
	const int count = in.u8() % 6;
	PlaneDesc planes[5];
	int64_t sizes[5];
	int fdOf[5];
	for (int i = 0; i < count; i++) {
		fdOf[i] = in.u8() % (fds + 1); // fds itself: an invalid fd
		planes[i].fd = fdOf[i] < fds ? 3 + fdOf[i] : -1;
		planes[i].offset = uint64_t(in.number());
		planes[i].length = uint64_t(in.number());
		sizes[i] = fdOf[i] < fds ? memorySize[fdOf[i]] : -1;
	}
	const Status checked = checkPlanes(planes, count, sizes, "fuzz buffer");
	if (!checked.ok()) {
		if (checked.code() != ErrorCode::CameraError || !fuzz::namesFile(checked.message(), "fuzz buffer"))
			fuzz::fail("a refused buffer is a CameraError naming it on one printable line",
				   checked.message());
		return 0;
	}
	// Mapped as mmap would: each plane at its offset in its fd's memory.
	MappedPlane mapped[5];
	for (int i = 0; i < count; i++) {
		if (planes[i].fd < 0 || planes[i].offset + planes[i].length > uint64_t(memorySize[fdOf[i]]))
			fuzz::fail("accepted planes lie in their memory", "");
		mapped[i].data = memory[fdOf[i]].get() + planes[i].offset;
		mapped[i].length = size_t(planes[i].length);
	}

	// The stream: format, size, stride, colour encoding (unsigned, as libcamera has them).
	const uint8_t k = in.u8();
	const uint32_t code = k < 2 * kFourccCount ? kFourccs[k % kFourccCount] : in.u32();
	const uint64_t modifier = (in.u8() & 7) == 7 ? in.u64() : 0;
	const int64_t width = int64_t(uint32_t(in.number())), height = int64_t(uint32_t(in.number()));
	const uint64_t stride = uint32_t(in.number());
	const YuvEncoding encoding = static_cast<YuvEncoding>(in.u8() % 4);
	ImageView view;
	const Status st = layoutFrame(code, modifier, "FMT", width, height, stride, mapped, count,
				      encoding, view);
	PixelFormat format;
	const bool known = calpedFormatForFourcc(code, modifier, format);
	if (!st.ok()) {
		if (!fuzz::printableLine(st.message()) ||
		    (st.code() == ErrorCode::UnsupportedPixelFormat) == known ||
		    (st.code() != ErrorCode::UnsupportedPixelFormat && st.code() != ErrorCode::CameraError))
			fuzz::fail("a refused frame is UnsupportedPixelFormat exactly for an unknown format, "
				   "else CameraError, on one printable line", st.message());
		return 0;
	}
	if (!known || view.format != format || view.width != width || view.height != height ||
	    width > kMaxFrameSide || height > kMaxFrameSide || view.yuv != encoding)
		fuzz::fail("an accepted frame has the stream's size and the format its fourcc maps to", "");
	const int64_t cw = (width + 1) / 2, ch = (height + 1) / 2;
	switch (format) {
	case PixelFormat::NV12:
		checkRows(view, 0, width, height, mapped[0]);
		checkRows(view, 1, 2 * cw, ch, mapped[count == 2 ? 1 : 0]);
		break;
	case PixelFormat::YUV420:
		checkRows(view, 0, width, height, mapped[0]);
		checkRows(view, 1, cw, ch, mapped[count == 3 ? 1 : 0]);
		checkRows(view, 2, cw, ch, mapped[count == 3 ? 2 : 0]);
		break;
	default:
		checkRows(view, 0, ImageView::packedRowBytes(format, int(width)), height, mapped[0]);
	}
	return 0;
}
