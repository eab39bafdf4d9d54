// SPDX-License-Identifier: BSD-2-Clause
#include "model_fixture.h"

#include "core/crc32.h"
#include "model/blob_format.h"
#include "model/byte_io.h"

namespace calped {
namespace test {

Model makeSmallModel(int32_t trees)
{
	Model m;
	m.name = "small";
	m.nTrees = trees;
	m.nodesPerTree = 7;
	m.treeDepth = 2;
	const uint32_t features = static_cast<uint32_t>(m.featureCount());
	// Node 0 splits into 1, 2; node 1 into 3, 4; node 2 into 5, 6 (0-based left children).
	const uint32_t children[7] = { 1, 3, 5, 0, 0, 0, 0 };
	for (int32_t t = 0; t < trees; t++) {
		for (uint32_t k = 0; k < 7; k++) {
			const uint32_t i = static_cast<uint32_t>(t) * 7 + k;
			const bool leaf = children[k] == 0;
			m.child.push_back(children[k]);
			m.fids.push_back(leaf ? 0 : (i * 733u + 11u) % features);
			m.thrs.push_back(leaf ? 0 : static_cast<int32_t>(i * 97 % 16384));
			m.hs.push_back(static_cast<int32_t>((i * 7919) % 60000) - 30000);
		}
	}
	return m;
}

Model makeUnusualModel()
{
	Model m;
	m.name = "unusual model: ~!+";
	ModelParams &p = m.params;
	p.modelDsH = 50.0f;
	p.modelDsW = 20.5f;
	p.modelDsPadH = 64;
	p.modelDsPadW = 32;
	p.stride = 8;
	p.cascThr = -1.25f;
	p.shrink = 2;
	p.colorSmooth = 2;
	p.gradNormRad = 3;
	p.gradNormConst = 0.0125f;
	p.gradColorChn = 2;
	p.gradFull = 1;
	p.histBinSize = 3;
	p.nOrients = 6;
	p.softBin = -1;
	p.nPerOct = 10;
	p.nOctUp = 1;
	p.nApprox = 9;
	p.lambdas[0] = 0.01f;
	p.lambdas[1] = 0.11047f;
	p.lambdas[2] = 0.10826f;
	p.padH = 8;
	p.padW = 6;
	p.minDsH = 51.0f;
	p.minDsW = 21.5f;
	p.pyramidSmooth = 0;
	p.nmsOverlap = 0.5f;
	p.nmsOverlapDenominator = NmsOverlapDenominator::Union;
	// LDCF-like: two 3x3 filters per channel, so the trees read 20 channels of 4x4 cells.
	p.nFilters = 2;
	p.filterSize = 3;
	for (int32_t i = 0; i < 2 * 10 * 9; i++)
		m.filters.push_back((i * 7717) % 65537 - 32768);
	// Uneven trees: tree 0 is a lone leaf, tree 1 reaches depth 3 with unused slots at the end.
	m.nTrees = 2;
	m.nodesPerTree = 9;
	m.treeDepth = 3;
	const uint32_t children[18] = { 0, 0, 0, 0, 0, 0, 0, 0, 0,
					1, 0, 3, 5, 0, 0, 0, 0, 0 };
	for (uint32_t i = 0; i < 18; i++) {
		m.child.push_back(children[i]);
		m.fids.push_back(children[i] ? 2559 - i : 0); // featureCount 16 * 8 * 20
		m.thrs.push_back(children[i] ? -100000 + static_cast<int32_t>(i) * 12345 : 0);
		m.hs.push_back(static_cast<int32_t>(i) * 1000 - 9000);
	}
	return m;
}

std::vector<uint8_t> versionOneBlob(const Model &acf)
{
	std::vector<uint8_t> blob = serializeModel(acf);
	// Version 2 put nFilters and filterSize right after the 28 version-1 parameter words.
	const size_t at = blob::kHeaderSize + 4 * blob::kParamWordsV1;
	blob.erase(blob.begin() + at, blob.begin() + at + 8);
	writeLe32(blob.data() + blob::kVersionOffset, 1);
	refreshChecksums(blob);
	return blob;
}

void refreshChecksums(std::vector<uint8_t> &blob)
{
	const uint64_t payloadSize = blob.size() - blob::kHeaderSize;
	writeLe32(blob.data() + blob::kPayloadSizeOffset, static_cast<uint32_t>(payloadSize));
	writeLe32(blob.data() + blob::kPayloadSizeOffset + 4, static_cast<uint32_t>(payloadSize >> 32));
	writeLe32(blob.data() + blob::kPayloadCrcOffset,
		  crc32(blob.data() + blob::kHeaderSize, blob.size() - blob::kHeaderSize));
	writeLe32(blob.data() + blob::kHeaderCrcOffset, crc32(blob.data(), blob::kHeaderCrcOffset));
}

} // namespace test
} // namespace calped
