// SPDX-License-Identifier: BSD-2-Clause
// The RGB8 input resize (resampleRgb8) alone, per kernel table, at the given ratios: a
// frame (a PNG, or random pixels) is resampled `--repeat` times. For wall time, for
// callgrind's per-function counts, or (with --table) for an instruction counter that only
// sees the whole program (scripts/cross-insns.sh's qemu plugin: the difference between
// two --repeat values, divided by their difference, is one frame):
//   bench_resize [--frame PNG] [--repeat K] [--table NAME] [--resize R]...
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "kernels.h"
#include "test_data.h"

using namespace calped;

int main(int argc, char **argv)
{
	std::string framePath, tableName;
	int repeat = 1;
	std::vector<double> ratios;
	for (int i = 1; i + 1 < argc; i += 2) {
		const std::string a = argv[i];
		if (a == "--frame")
			framePath = argv[i + 1];
		else if (a == "--repeat")
			repeat = std::atoi(argv[i + 1]);
		else if (a == "--table")
			tableName = argv[i + 1];
		else if (a == "--resize")
			ratios.push_back(std::atof(argv[i + 1]));
	}
	if (ratios.empty())
		ratios = { 1.5, 2.0, 2.5 };
	test::RgbImage img;
	if (!test::loadFrameOrSynthetic(framePath, "bench_resize", img))
		return 1;
	const int w = img.width, h = img.height;
	const kernels::KernelTable *tables[8];
	const int nTables = kernels::availableKernelTables(tables, 8);
	std::vector<int32_t> rowTmp(3 * size_t(w) + 8);
	unsigned checksum = 0;
	for (double r : ratios) {
		const int w1 = int(std::lround(w * r)), h1 = int(std::lround(h * r));
		std::vector<kernels::ResampleTap> xt(w1), yt(h1);
		if (!kernels::buildResampleTaps(w, w1, 1.0, xt.data()) ||
		    !kernels::buildResampleTaps(h, h1, 1.0, yt.data())) {
			std::fprintf(stderr, "bench_resize: ratio %g too small\n", r);
			return 1;
		}
		std::vector<uint8_t> out(size_t(w1) * h1 * 3);
		for (int t = 0; t < nTables; t++) {
			const kernels::KernelTable &k = *tables[t];
			if (!tableName.empty() && tableName != k.name)
				continue;
			const auto t0 = std::chrono::steady_clock::now();
			for (int i = 0; i < repeat; i++) {
				k.resampleRgb8(img.pixels.data(), 3 * w, w, h, out.data(), 3 * w1, w1, h1, xt.data(),
					       yt.data(), rowTmp.data());
				checksum += out[i % out.size()];
			}
			const double ms = std::chrono::duration<double, std::milli>(
						  std::chrono::steady_clock::now() - t0).count();
			std::printf("resize %.2f %-5s %8.3f ms per %dx%d -> %dx%d frame\n", r, k.name,
				    ms / repeat, w, h, w1, h1);
		}
	}
	std::printf("checksum %u\n", checksum);
	return 0;
}
