// SPDX-License-Identifier: BSD-2-Clause
// The pixel-format conversion kernels alone, every table (ref, opt): a frame (a PNG, or
// random pixels) is encoded to each camera format and converted back to RGB8 `--repeat`
// times, in 8-row strips as the detector does. Meant for callgrind, whose per-function
// instruction counts compare the tables (docs/pixel-formats.md):
//   valgrind --tool=callgrind bench_convert [--frame PNG] [--repeat K]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "kernels.h"
#include "pixel_formats.h"
#include "test_data.h"

using namespace calped;

int main(int argc, char **argv)
{
	std::string framePath;
	int repeat = 1;
	for (int i = 1; i + 1 < argc; i += 2) {
		const std::string a = argv[i];
		if (a == "--frame")
			framePath = argv[i + 1];
		else if (a == "--repeat")
			repeat = std::atoi(argv[i + 1]);
	}
	test::RgbImage img;
	if (!test::loadFrameOrSynthetic(framePath, "bench_convert", img))
		return 1;
	const int w = img.width, h = img.height;
	const PixelFormat formats[] = { PixelFormat::BGR8, PixelFormat::Gray8, PixelFormat::NV12,
					PixelFormat::YUV420, PixelFormat::YUYV, PixelFormat::BayerRGGB8 };
	const kernels::ConvertKernels *tables[4];
	const int nTables = kernels::availableConvertKernels(tables, 4);
	std::vector<uint8_t> strip(size_t(8) * 3 * w);
	unsigned checksum = 0;
	for (PixelFormat f : formats) {
		const auto frame = test::encodeImage(img.pixels.data(), w, h, f);
		const ImageView v = frame.view();
		kernels::RawFrame raw;
		for (int i = 0; i < 3; i++) {
			raw.planes[i] = v.planes[i];
			raw.strides[i] = v.strides[i];
		}
		raw.width = w;
		raw.height = h;
		raw.yuv = kernels::yuvCoeffs(false, false);
		if (f == PixelFormat::NV12) {
			raw.planes[2] = v.planes[1] + 1;
			raw.strides[2] = v.strides[1];
			raw.chromaStep = 2;
		}
		for (int t = 0; t < nTables; t++) {
			const kernels::ConvertKernels &k = *tables[t];
			const kernels::ConvertRowsFn fn =
				f == PixelFormat::BGR8 ? k.bgr8 : f == PixelFormat::Gray8 ? k.gray8 :
				f == PixelFormat::YUYV ? k.yuyv : f == PixelFormat::BayerRGGB8 ? k.bayer : k.yuv420;
			const auto t0 = std::chrono::steady_clock::now();
			for (int r = 0; r < repeat; r++)
				for (int y0 = 0; y0 < h; y0 += 8) {
					fn(raw, y0, std::min(8, h - y0), strip.data(), 3 * w);
					checksum += strip[0];
				}
			const double ms = std::chrono::duration<double, std::milli>(
						  std::chrono::steady_clock::now() - t0).count();
			std::printf("%-10s %-4s %7.3f ms per %dx%d frame\n", pixelFormatName(f), k.name,
				    ms / repeat, w, h);
		}
	}
	std::printf("checksum %u\n", checksum);
	return 0;
}
