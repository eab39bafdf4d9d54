// SPDX-License-Identifier: BSD-2-Clause
// libcamera formats and buffer layouts as ImageViews: every supported format, odd sizes,
// padded strides, one plane per colour plane or all of them in one, and bad layouts.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include <libcamera/color_space.h>
#include <libcamera/formats.h>

#include "format_map.h"

namespace calped {
namespace ports {
namespace {

namespace lf = libcamera::formats;

// A frame's memory: planes carved out of one byte vector.
struct Buffer {
	std::vector<uint8_t> bytes;
	MappedPlane planes[3];
	int count = 0;

	// Consecutive planes of the given lengths.
	explicit Buffer(std::vector<size_t> lengths)
	{
		size_t total = 0;
		for (size_t l : lengths)
			total += l;
		bytes.assign(total, 0);
		size_t at = 0;
		for (size_t l : lengths) {
			planes[count++] = MappedPlane{ bytes.data() + at, l };
			at += l;
		}
	}
	// All planes described as one.
	MappedPlane whole() const { return MappedPlane{ bytes.data(), bytes.size() }; }
};

struct Supported {
	libcamera::PixelFormat lc;
	PixelFormat calped;
};

const Supported kSupported[] = {
	{ lf::NV12, PixelFormat::NV12 },     { lf::YUV420, PixelFormat::YUV420 },
	{ lf::YUYV, PixelFormat::YUYV },     { lf::RGB888, PixelFormat::BGR8 },
	{ lf::BGR888, PixelFormat::RGB8 },   { lf::R8, PixelFormat::Gray8 },
	{ lf::SRGGB8, PixelFormat::BayerRGGB8 }, { lf::SGRBG8, PixelFormat::BayerGRBG8 },
	{ lf::SGBRG8, PixelFormat::BayerGBRG8 }, { lf::SBGGR8, PixelFormat::BayerBGGR8 },
};

TEST(LibcameraFormatMap, EverySupportedFormatMapsBothWays)
{
	for (const Supported &s : kSupported) {
		PixelFormat calped;
		ASSERT_TRUE(calpedFormatFor(s.lc, calped)) << s.lc.toString();
		EXPECT_EQ(calped, s.calped) << s.lc.toString();
		libcamera::PixelFormat back;
		ASSERT_TRUE(libcameraFormatFor(s.calped, back)) << pixelFormatName(s.calped);
		EXPECT_EQ(back, s.lc) << pixelFormatName(s.calped);
	}
}

TEST(LibcameraFormatMap, RgbNamesFollowDrmByteOrder)
{
	// DRM fourccs name little-endian words: libcamera's RGB888 is B,G,R in memory.
	PixelFormat f;
	ASSERT_TRUE(calpedFormatFor(lf::RGB888, f));
	EXPECT_EQ(f, PixelFormat::BGR8);
	ASSERT_TRUE(calpedFormatFor(lf::BGR888, f));
	EXPECT_EQ(f, PixelFormat::RGB8);
}

TEST(LibcameraFormatMap, UnsupportedFormatsAreRejected)
{
	const libcamera::PixelFormat unsupported[] = { lf::MJPEG, lf::XRGB8888, lf::NV21,
						       lf::SRGGB10, lf::UYVY };
	for (const libcamera::PixelFormat &f : unsupported) {
		PixelFormat calped;
		EXPECT_FALSE(calpedFormatFor(f, calped)) << f.toString();
		Buffer b({ 1 << 16 });
		ImageView view;
		Status st = frameView(f, 64, 48, 256, b.planes, 1, YuvEncoding::Bt601Limited, view);
		EXPECT_EQ(st.code(), ErrorCode::UnsupportedPixelFormat) << f.toString();
		EXPECT_NE(std::strstr(st.message(), f.toString().c_str()), nullptr) << st.message();
	}
}

// Odd width and height, stride padded beyond the row.
TEST(LibcameraFormatMap, Nv12TwoPlanesOddSizePaddedStride)
{
	const int w = 641, h = 481, stride = 704;
	const int chromaRows = 241;
	Buffer b({ size_t(stride) * h, size_t(stride) * chromaRows });
	ImageView v;
	Status st = frameView(lf::NV12, w, h, stride, b.planes, 2, YuvEncoding::Bt709Full, v);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(v.format, PixelFormat::NV12);
	EXPECT_EQ(v.width, w);
	EXPECT_EQ(v.height, h);
	EXPECT_EQ(v.planes[0], b.planes[0].data);
	EXPECT_EQ(v.planes[1], b.planes[1].data);
	EXPECT_EQ(v.planes[2], nullptr);
	EXPECT_EQ(v.strides[0], stride);
	EXPECT_EQ(v.strides[1], stride);
	EXPECT_EQ(v.yuv, YuvEncoding::Bt709Full);
}

TEST(LibcameraFormatMap, Nv12OnePlaneHoldsChromaAfterLuma)
{
	const int w = 639, h = 479, stride = 640;
	Buffer b({ size_t(stride) * h + size_t(stride) * 240 });
	ImageView v;
	Status st = frameView(lf::NV12, w, h, stride, b.planes, 1, YuvEncoding::Bt601Limited, v);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(v.planes[0], b.bytes.data());
	EXPECT_EQ(v.planes[1], b.bytes.data() + size_t(stride) * h);
	EXPECT_EQ(v.strides[1], stride);
}

TEST(LibcameraFormatMap, Nv12ShortChromaPlaneIsAnError)
{
	const int w = 641, h = 481, stride = 704;
	// One byte short of the last chroma row (which needs 2 * 321 bytes).
	Buffer b({ size_t(stride) * h, size_t(stride) * 240 + 2 * 321 - 1 });
	ImageView v;
	Status st = frameView(lf::NV12, w, h, stride, b.planes, 2, YuvEncoding::Bt601Limited, v);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "plane 1"), nullptr) << st.message();
	EXPECT_NE(std::strstr(st.message(), "169601"), nullptr) << st.message(); // 704*240+642-1
	// Exactly long enough is fine: the last row needs no padding.
	Buffer exact({ size_t(stride) * h, size_t(stride) * 240 + 2 * 321 });
	EXPECT_TRUE(frameView(lf::NV12, w, h, stride, exact.planes, 2, YuvEncoding::Bt601Limited, v)
			    .ok());
}

TEST(LibcameraFormatMap, Yuv420ThreePlanesOddSize)
{
	const int w = 641, h = 481, stride = 672; // chroma stride 336 >= 321
	const size_t ySize = size_t(stride) * h, cSize = size_t(stride / 2) * 241;
	Buffer b({ ySize, cSize, cSize });
	ImageView v;
	Status st = frameView(lf::YUV420, w, h, stride, b.planes, 3, YuvEncoding::Bt601Full, v);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(v.format, PixelFormat::YUV420);
	EXPECT_EQ(v.planes[0], b.planes[0].data);
	EXPECT_EQ(v.planes[1], b.planes[1].data);
	EXPECT_EQ(v.planes[2], b.planes[2].data);
	EXPECT_EQ(v.strides[0], stride);
	EXPECT_EQ(v.strides[1], stride / 2);
	EXPECT_EQ(v.strides[2], stride / 2);
	EXPECT_EQ(v.yuv, YuvEncoding::Bt601Full);
}

TEST(LibcameraFormatMap, Yuv420OnePlaneIsYThenUThenV)
{
	const int w = 320, h = 241, stride = 384;
	const size_t ySize = size_t(stride) * h, cSize = size_t(stride / 2) * 121;
	Buffer b({ ySize + 2 * cSize });
	ImageView v;
	Status st = frameView(lf::YUV420, w, h, stride, b.planes, 1, YuvEncoding::Bt601Limited, v);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_EQ(v.planes[1], b.bytes.data() + ySize);
	EXPECT_EQ(v.planes[2], b.bytes.data() + ySize + cSize);
	EXPECT_EQ(v.strides[1], stride / 2);
}

TEST(LibcameraFormatMap, Yuv420ChromaStrideTooShortForOddWidth)
{
	// Stride 641 halves to 320, one short of ceil(641 / 2) chroma samples.
	const int w = 641, h = 4, stride = 641;
	Buffer b({ size_t(stride) * h, 4096, 4096 });
	ImageView v;
	Status st = frameView(lf::YUV420, w, h, stride, b.planes, 3, YuvEncoding::Bt601Limited, v);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "stride 320"), nullptr) << st.message();
}

TEST(LibcameraFormatMap, Yuv420TwoPlanesIsAnError)
{
	Buffer b({ 64 * 48, 64 * 48 });
	ImageView v;
	Status st = frameView(lf::YUV420, 64, 48, 64, b.planes, 2, YuvEncoding::Bt601Limited, v);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "2 planes"), nullptr) << st.message();
}

// Every one-plane format, odd width, padded stride, and one byte short.
TEST(LibcameraFormatMap, PackedFormatsOddWidthPaddedStride)
{
	const int w = 333, h = 17;
	for (const Supported &s : kSupported) {
		if (s.calped == PixelFormat::NV12 || s.calped == PixelFormat::YUV420)
			continue;
		const int rowBytes = ImageView::packedRowBytes(s.calped, w);
		const int stride = (rowBytes + 63) / 64 * 64 + 64;
		const size_t needed = size_t(stride) * (h - 1) + rowBytes;
		Buffer b({ needed });
		ImageView v;
		Status st = frameView(s.lc, w, h, stride, b.planes, 1, YuvEncoding::Bt709Limited, v);
		ASSERT_TRUE(st.ok()) << s.lc.toString() << ": " << st.message();
		EXPECT_EQ(v.format, s.calped) << s.lc.toString();
		EXPECT_EQ(v.planes[0], b.bytes.data());
		EXPECT_EQ(v.strides[0], stride);
		EXPECT_EQ(v.width, w);
		EXPECT_EQ(v.height, h);

		MappedPlane shortPlane{ b.bytes.data(), needed - 1 };
		st = frameView(s.lc, w, h, stride, &shortPlane, 1, YuvEncoding::Bt601Limited, v);
		EXPECT_EQ(st.code(), ErrorCode::CameraError) << s.lc.toString();

		// A stride shorter than one row.
		st = frameView(s.lc, w, h, rowBytes - 1, b.planes, 1, YuvEncoding::Bt601Limited, v);
		EXPECT_EQ(st.code(), ErrorCode::CameraError) << s.lc.toString();
		EXPECT_NE(std::strstr(st.message(), "shorter than a row"), nullptr) << st.message();
	}
}

TEST(LibcameraFormatMap, YuyvOddWidthRoundsUpToWholePairs)
{
	// 333 pixels are 167 Y,U,Y,V pairs: 668 bytes per row.
	Buffer b({ 668 * 3 });
	ImageView v;
	EXPECT_TRUE(frameView(lf::YUYV, 333, 3, 668, b.planes, 1, YuvEncoding::Bt601Limited, v).ok());
	EXPECT_EQ(frameView(lf::YUYV, 333, 3, 667, b.planes, 1, YuvEncoding::Bt601Limited, v).code(),
		  ErrorCode::CameraError);
}

TEST(LibcameraFormatMap, OnePlaneFormatWithTwoPlanesIsAnError)
{
	Buffer b({ 64 * 3 * 8, 64 });
	ImageView v;
	Status st = frameView(lf::RGB888, 64, 8, 192, b.planes, 2, YuvEncoding::Bt601Limited, v);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
}

TEST(LibcameraFormatMap, EmptySizeIsAnError)
{
	Buffer b({ 4096 });
	ImageView v;
	EXPECT_EQ(frameView(lf::NV12, 0, 16, 64, b.planes, 1, YuvEncoding::Bt601Limited, v).code(),
		  ErrorCode::CameraError);
}

// The table in frame_layout.h is libcamera's: every fourcc is the libcamera format's.
TEST(LibcameraFormatMap, FourccsAreLibcamerasFormats)
{
	EXPECT_EQ(kFourccNV12, lf::NV12.fourcc());
	EXPECT_EQ(kFourccYUV420, lf::YUV420.fourcc());
	EXPECT_EQ(kFourccYUYV, lf::YUYV.fourcc());
	EXPECT_EQ(kFourccRGB888, lf::RGB888.fourcc());
	EXPECT_EQ(kFourccBGR888, lf::BGR888.fourcc());
	EXPECT_EQ(kFourccR8, lf::R8.fourcc());
	EXPECT_EQ(kFourccSRGGB8, lf::SRGGB8.fourcc());
	EXPECT_EQ(kFourccSGRBG8, lf::SGRBG8.fourcc());
	EXPECT_EQ(kFourccSGBRG8, lf::SGBRG8.fourcc());
	EXPECT_EQ(kFourccSBGGR8, lf::SBGGR8.fourcc());
	// A known fourcc with a modifier (a tiled or compressed layout) is not that format.
	PixelFormat f;
	EXPECT_FALSE(calpedFormatFor(libcamera::PixelFormat(kFourccNV12, 1), f));
}

// Sizes as libcamera gives them (unsigned): a side past kMaxFrameSide is refused, not
// wrapped into int or multiplied past INT_MAX (fuzz target libcamera: 3 x 0x60000000
// overflowed int in the row size; tests/fuzz/regressions/libcamera/).
TEST(LibcameraFormatMap, SidesBeyondTheMaximumAreRefused)
{
	Buffer b({ 1 << 16 });
	ImageView v;
	Status st = frameView(lf::RGB888, 0x60000000, 1, 4096, b.planes, 1, YuvEncoding::Bt601Limited, v);
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "1610612736x1"), nullptr) << st.message();
	EXPECT_EQ(frameView(lf::NV12, 4294967295u, 2, 4096, b.planes, 1, YuvEncoding::Bt601Limited, v).code(),
		  ErrorCode::CameraError);
	EXPECT_EQ(frameView(lf::R8, 16, kMaxFrameSide + 1, 16, b.planes, 1, YuvEncoding::Bt601Limited, v).code(),
		  ErrorCode::CameraError);
	EXPECT_TRUE(frameView(lf::R8, 16, 16, 16, b.planes, 1, YuvEncoding::Bt601Limited, v).ok());
}

// The plane descriptions are checked before anything is mapped, without a file.
TEST(LibcameraFormatMap, PlanesAreCheckedAgainstTheirMemoryBeforeMapping)
{
	const PlaneDesc fits[2] = { { 5, 0, 3072 }, { 5, 3072, 1536 } };
	const int64_t sizes[2] = { 4608, 4608 };
	EXPECT_TRUE(checkPlanes(fits, 2, sizes, "buffer 0").ok());
	const int64_t smaller[2] = { 4607, 4607 };
	Status st = checkPlanes(fits, 2, smaller, "buffer 0");
	EXPECT_EQ(st.code(), ErrorCode::CameraError);
	EXPECT_NE(std::strstr(st.message(), "buffer 0 plane 1"), nullptr) << st.message();
	const int64_t unknown[2] = { -1, -1 }; // the fd cannot tell: not checked
	EXPECT_TRUE(checkPlanes(fits, 2, unknown, "buffer 0").ok());
	const PlaneDesc overflow[1] = { { 5, UINT64_MAX - 10, 11 } };
	EXPECT_NE(std::strstr(checkPlanes(overflow, 1, sizes, "b").message(), "overflows"), nullptr);
	EXPECT_FALSE(checkPlanes(fits, 0, sizes, "b").ok());
	EXPECT_FALSE(checkPlanes(fits, BufferMapping::kMaxPlanes + 1, sizes, "b").ok());
}

TEST(LibcameraFormatMap, YuvEncodingFromColourSpace)
{
	using CS = libcamera::ColorSpace;
	EXPECT_EQ(yuvEncodingFor(std::nullopt), YuvEncoding::Bt601Limited);
	EXPECT_EQ(yuvEncodingFor(CS::Smpte170m), YuvEncoding::Bt601Limited);
	EXPECT_EQ(yuvEncodingFor(CS::Sycc), YuvEncoding::Bt601Full);
	EXPECT_EQ(yuvEncodingFor(CS::Rec709), YuvEncoding::Bt709Limited);
	EXPECT_EQ(yuvEncodingFor(CS(CS::Primaries::Rec709, CS::TransferFunction::Rec709,
				    CS::YcbcrEncoding::Rec709, CS::Range::Full)),
		  YuvEncoding::Bt709Full);
	// calped reads BT.2020 as its nearest neighbour, BT.709.
	EXPECT_EQ(yuvEncodingFor(CS::Rec2020), YuvEncoding::Bt709Limited);
}

} // namespace
} // namespace ports
} // namespace calped
