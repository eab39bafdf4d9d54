// SPDX-License-Identifier: BSD-2-Clause
// What a GigE Vision camera answers, as the Aravis port checks it (ports/aravis/
// pixel_formats.h, no camera): the stream announced at connection (pixel format, region,
// payload, the format's name from the camera's description) and then received images'
// leaders (format, size, row padding, bytes received); the input's last bytes are a reply
// to the GVCP probe (gvcp_probe.h). An accepted stream must be one the port can allocate
// and read; an accepted image a view whose every row lies inside the received bytes (each
// row is read, so ASan sees an overread); a refusal one printable line; a reply is the
// probe's answer only if it is a READREG acknowledge of the probe's request with its value.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>

#include "fuzz_checks.h"
#include "fuzz_input.h"

#include "gvcp_probe.h"
#include "pixel_formats.h"

namespace {

using namespace calped;
using namespace calped::ports;

const uint32_t kPfncs[] = { kPfncMono8,    kPfncRGB8,     kPfncBGR8,     kPfncYUYV,
			    kPfncBayerRG8, kPfncBayerGR8, kPfncBayerGB8, kPfncBayerBG8,
			    kPfncYUV422Packed, 0x01100007u /* Mono16 */ };

uint32_t pickPfnc(fuzz::Input &in)
{
	const uint8_t k = in.u8();
	return k < 2 * (sizeof(kPfncs) / sizeof(kPfncs[0])) ? kPfncs[k % (sizeof(kPfncs) / sizeof(kPfncs[0]))]
							     : in.u32();
}

// Reads every row of a view (rowBytes each, stride apart); fails unless all lie in [begin, end).
void readRows(const ImageView &v, int rowBytes, const uint8_t *begin, const uint8_t *end)
{
	const uintptr_t b = reinterpret_cast<uintptr_t>(begin), e = reinterpret_cast<uintptr_t>(end);
	volatile uint8_t sink = 0;
	for (int y = 0; y < v.height; y++) {
		const uint8_t *row = v.planes[0] + size_t(y) * size_t(v.strides[0]);
		const uintptr_t r = reinterpret_cast<uintptr_t>(row);
		if (r < b || r + size_t(rowBytes) > e)
			fuzz::fail("every row of an accepted image lies in the received bytes", "");
		sink = sink + row[0] + row[rowBytes - 1];
	}
	(void)sink;
}

void checkLeader(fuzz::Input &in, const StreamPlan *plan)
{
	// The leader: the format and size the image says it has (often the announced ones).
	const bool announced = (in.u8() & 1) && plan; // the byte is read either way
	const uint32_t pfnc = pickPfnc(in);
	int width = static_cast<int>(in.number()), height = static_cast<int>(in.number());
	PixelFormat format;
	if (announced) {
		format = plan->format;
		width = plan->width;
		height = plan->height;
	} else if (!pixelFormatFromPfnc(pfnc, format)) {
		return; // the port refuses the buffer before asking for a view
	}
	const int padX = static_cast<int>(in.number());
	// Bytes received: up to the payload (our buffers hold that much), at most 256 KiB here.
	size_t size = size_t(in.bits(3)) % ((1u << 18) + 1);
	if (plan && size > plan->payload)
		size = plan->payload;
	std::unique_ptr<uint8_t[]> bytes(new uint8_t[size]); // exactly: ASan sees past it
	ImageView view;
	if (!viewReceivedImage(format, bytes.get(), size, width, height, padX, view))
		return;
	const int rowBytes = ImageView::packedRowBytes(format, width);
	if (view.format != format || view.width != width || view.height != height ||
	    view.planes[0] != bytes.get() || rowBytes <= 0 || view.strides[0] < rowBytes ||
	    width > kMaxCameraSide || height > kMaxCameraSide)
		fuzz::fail("an accepted image is the leader's format and size, rows within the stride", "");
	readRows(view, rowBytes, bytes.get(), bytes.get() + size);
}

// The rest of the input as a datagram on the probe's socket, in a block of exactly its size.
void checkProbeReply(fuzz::Input &in)
{
	const size_t n = in.left();
	std::unique_ptr<uint8_t[]> reply(new uint8_t[n]);
	if (n)
		std::memcpy(reply.get(), in.rest(), n);
	const uint8_t *r = reply.get();
	const bool expected = n >= 12 && r[2] == 0x00 && r[3] == 0x81 && r[4] == 0 && r[5] == 4 &&
			      r[6] == (kGvcpProbeRequestId >> 8) && r[7] == (kGvcpProbeRequestId & 0xff);
	if (isProbeAnswer(r, n) != expected)
		fuzz::fail("a reply is the probe's answer exactly when it acknowledges its READREG", "");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fuzz::Input in(data, size);
	AnnouncedStream a;
	a.pfnc = pickPfnc(in);
	a.width = in.number();
	a.height = in.number();
	a.payload = in.number();
	// The camera's name for its format: up to 40 bytes of anything, NUL-terminated.
	char name[41] = {};
	const size_t n = in.u8() % 41;
	for (size_t i = 0; i < n; i++)
		name[i] = static_cast<char>(in.u8());

	StreamPlan plan;
	const Status st = planStream(a, name, plan);
	if (!st.ok()) {
		if (st.code() != ErrorCode::CameraError || !fuzz::printableLine(st.message()))
			fuzz::fail("a refused stream is a CameraError on one printable line", st.message());
		checkLeader(in, nullptr);
		checkProbeReply(in);
		return 0;
	}
	PixelFormat format;
	if (!pixelFormatFromPfnc(a.pfnc, format) || format != plan.format)
		fuzz::fail("an accepted stream has the mapped format", "");
	const int64_t image = int64_t(ImageView::packedRowBytes(format, plan.width)) * plan.height;
	if (plan.width != a.width || plan.height != a.height || plan.width < 1 || plan.height < 1 ||
	    plan.width > kMaxCameraSide || plan.height > kMaxCameraSide ||
	    int64_t(plan.payload) != a.payload || a.payload < image ||
	    a.payload > 2 * image + int64_t(kPayloadSlackBytes))
		fuzz::fail("an accepted stream's size and payload are the camera's and hold one image", "");
	checkLeader(in, &plan);
	checkProbeReply(in);
	return 0;
}
