// SPDX-License-Identifier: BSD-2-Clause
#include "synthetic.h"

#include <random>

namespace calped {
namespace test {

Model randomModel(uint32_t seed, int nTrees)
{
	std::mt19937 rng(seed);
	Model m;
	m.name = "random";
	m.nTrees = nTrees;
	m.nodesPerTree = 7;
	m.treeDepth = 2;
	const int nFeatures = m.featureCount();
	std::uniform_int_distribution<int> fid(0, nFeatures - 1);
	std::uniform_int_distribution<int> thr(0, 16384);
	std::uniform_real_distribution<double> leaf(-0.5, 0.5);
	const uint32_t child[7] = { 1, 3, 5, 0, 0, 0, 0 };
	for (int t = 0; t < nTrees; t++) {
		for (int k = 0; k < 7; k++) {
			m.fids.push_back(k < 3 ? fid(rng) : 0);
			m.thrs.push_back(k < 3 ? thr(rng) : 0);
			m.child.push_back(child[k]);
			m.hs.push_back(k < 3 ? 0 : int32_t(leaf(rng) * 65536));
		}
	}
	return m;
}

Model randomLdcfModel(uint32_t seed, int nTrees)
{
	Model m = randomModel(seed, nTrees);
	ModelParams &p = m.params;
	p.shrink = 2;
	p.histBinSize = 2;
	p.padH = 14;
	p.padW = 12;
	p.nFilters = 4;
	p.filterSize = 5;
	std::mt19937 rng(seed + 1);
	std::uniform_int_distribution<int> weight(-16384, 16384), thr(-8192, 8192);
	m.filters.resize(size_t(p.nFilters) * 10 * 25);
	for (auto &f : m.filters)
		f = weight(rng);
	std::uniform_int_distribution<int> fid(0, m.featureCount() - 1);
	for (size_t i = 0; i < m.fids.size(); i++)
		if (m.child[i] != 0) {
			m.fids[i] = uint32_t(fid(rng));
			m.thrs[i] = thr(rng);
		}
	return m;
}

std::vector<uint8_t> randomImage(uint32_t seed, int width, int height)
{
	std::mt19937 rng(seed);
	std::uniform_int_distribution<int> noise(-12, 12);
	std::vector<uint8_t> img(size_t(width) * height * 3);
	for (int y = 0; y < height; y++)
		for (int x = 0; x < width; x++)
			for (int c = 0; c < 3; c++) {
				int v = (x * (c + 1) * 255) / (width + 1) / 2 + (y * 255) / (height + 1) / 3;
				if (((x / 17) + (y / 29)) % 3 == c)
					v += 60;
				v += noise(rng);
				img[(size_t(y) * width + x) * 3 + c] = uint8_t(v < 0 ? 0 : (v > 255 ? 255 : v));
			}
	return img;
}

bool syntheticCamera(CameraModel &out)
{
	Eigen::Matrix3d K;
	K << 300, 0, 160, 0, 300, 60, 0, 0, 1;
	Eigen::Matrix3d R;
	R << 1, 0, 0, 0, 0, -1, 0, 1, 0;
	return CameraModel::fromPinhole(K, R, Eigen::Vector3d(0, 2.0, 0), LengthUnit::Metre, out).ok();
}

} // namespace test
} // namespace calped
