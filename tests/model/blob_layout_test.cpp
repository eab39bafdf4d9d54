// SPDX-License-Identifier: BSD-2-Clause
// The blob round-trips and has exactly the layout docs/model-format.md describes.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include <calped/model.h>

#include "core/crc32.h"
#include "model/byte_io.h"
#include "model_fixture.h"

namespace calped {
namespace {

void expectSameModel(const Model &a, const Model &b)
{
	EXPECT_EQ(a.name, b.name);
	const ModelParams &p = a.params, &q = b.params;
	// Floats compared bit for bit: the blob stores their IEEE-754 patterns.
	EXPECT_EQ(floatBits(p.modelDsH), floatBits(q.modelDsH));
	EXPECT_EQ(floatBits(p.modelDsW), floatBits(q.modelDsW));
	EXPECT_EQ(p.modelDsPadH, q.modelDsPadH);
	EXPECT_EQ(p.modelDsPadW, q.modelDsPadW);
	EXPECT_EQ(p.stride, q.stride);
	EXPECT_EQ(floatBits(p.cascThr), floatBits(q.cascThr));
	EXPECT_EQ(p.shrink, q.shrink);
	EXPECT_EQ(p.colorSmooth, q.colorSmooth);
	EXPECT_EQ(p.gradNormRad, q.gradNormRad);
	EXPECT_EQ(floatBits(p.gradNormConst), floatBits(q.gradNormConst));
	EXPECT_EQ(p.gradColorChn, q.gradColorChn);
	EXPECT_EQ(p.gradFull, q.gradFull);
	EXPECT_EQ(p.histBinSize, q.histBinSize);
	EXPECT_EQ(p.nOrients, q.nOrients);
	EXPECT_EQ(p.softBin, q.softBin);
	EXPECT_EQ(p.nPerOct, q.nPerOct);
	EXPECT_EQ(p.nOctUp, q.nOctUp);
	EXPECT_EQ(p.nApprox, q.nApprox);
	for (int i = 0; i < 3; i++)
		EXPECT_EQ(floatBits(p.lambdas[i]), floatBits(q.lambdas[i])) << "lambdas[" << i << "]";
	EXPECT_EQ(p.padH, q.padH);
	EXPECT_EQ(p.padW, q.padW);
	EXPECT_EQ(floatBits(p.minDsH), floatBits(q.minDsH));
	EXPECT_EQ(floatBits(p.minDsW), floatBits(q.minDsW));
	EXPECT_EQ(p.pyramidSmooth, q.pyramidSmooth);
	EXPECT_EQ(floatBits(p.nmsOverlap), floatBits(q.nmsOverlap));
	EXPECT_EQ(p.nmsOverlapDenominator, q.nmsOverlapDenominator);
	EXPECT_EQ(p.nFilters, q.nFilters);
	EXPECT_EQ(p.filterSize, q.filterSize);
	EXPECT_EQ(a.filters, b.filters);
	EXPECT_EQ(a.nTrees, b.nTrees);
	EXPECT_EQ(a.nodesPerTree, b.nodesPerTree);
	EXPECT_EQ(a.treeDepth, b.treeDepth);
	EXPECT_EQ(a.fids, b.fids);
	EXPECT_EQ(a.thrs, b.thrs);
	EXPECT_EQ(a.child, b.child);
	EXPECT_EQ(a.hs, b.hs);
}

TEST(ModelBlob, RoundTripPreservesEveryParameterAndArray)
{
	for (const Model &m : { test::makeSmallModel(5), test::makeUnusualModel() }) {
		ASSERT_TRUE(validateModel(m).ok()) << validateModel(m).message();
		const std::vector<uint8_t> blob = serializeModel(m);
		ASSERT_FALSE(blob.empty());
		Model loaded;
		const Status s = loadModel(blob.data(), blob.size(), loaded);
		ASSERT_TRUE(s.ok()) << s.message();
		expectSameModel(m, loaded);
		// Serialising again gives the same bytes: nothing depends on uninitialised state.
		EXPECT_EQ(serializeModel(loaded), blob);
	}
}

TEST(ModelBlob, UnusualModelDiffersFromDefaultsInEveryParameter)
{
	// Guards the round-trip test above: a field equal to its default would hide a bug.
	const std::vector<uint8_t> unusual = serializeModel(test::makeUnusualModel());
	Model defaults = test::makeUnusualModel();
	defaults.params = ModelParams();
	// The filter shape must match the weights to serialise; its words are compared below.
	defaults.params.nFilters = 2;
	defaults.params.filterSize = 3;
	EXPECT_NE(ModelParams().nFilters, 2);
	EXPECT_NE(ModelParams().filterSize, 3);
	const std::vector<uint8_t> plain = serializeModel(defaults);
	ASSERT_EQ(unusual.size(), plain.size());
	for (size_t offset = 32; offset < 144; offset += 4) {
		if (offset == 84)
			continue; // nOrients: 6 is the only accepted value
		EXPECT_NE(readLe32(unusual.data() + offset), readLe32(plain.data() + offset))
			<< "parameter word at offset " << offset;
	}
}

TEST(ModelBlob, HeaderAndFieldOffsetsMatchTheDocumentedLayout)
{
	const Model m = test::makeUnusualModel();
	const std::vector<uint8_t> blob = serializeModel(m);
	const size_t nameLength = m.name.size();
	const size_t nodes = static_cast<size_t>(m.nTrees * m.nodesPerTree);
	const size_t weights = m.filters.size();
	ASSERT_EQ(weights, 2u * 10u * 3u * 3u);
	ASSERT_EQ(blob.size(), 168 + nameLength + 4 * weights + 16 * nodes);

	EXPECT_EQ(std::memcmp(blob.data(), "CALPEDM\0", 8), 0);
	EXPECT_EQ(readLe32(&blob[8]), 2u);   // version
	EXPECT_EQ(readLe32(&blob[12]), 32u); // header size
	EXPECT_EQ(readLe64(&blob[16]), blob.size() - 32);
	EXPECT_EQ(readLe32(&blob[24]), crc32(blob.data() + 32, blob.size() - 32));
	EXPECT_EQ(readLe32(&blob[28]), crc32(blob.data(), 28));

	const ModelParams &p = m.params;
	EXPECT_EQ(readLe32(&blob[32]), floatBits(p.modelDsH));
	EXPECT_EQ(readLe32(&blob[36]), floatBits(p.modelDsW));
	EXPECT_EQ(readLe32(&blob[40]), 64u);
	EXPECT_EQ(readLe32(&blob[48]), 8u); // stride
	EXPECT_EQ(readLe32(&blob[52]), floatBits(p.cascThr));
	EXPECT_EQ(readLe32(&blob[56]), 2u); // shrink
	EXPECT_EQ(readLe32(&blob[88]), static_cast<uint32_t>(-1)); // softBin
	EXPECT_EQ(readLe32(&blob[104]), floatBits(p.lambdas[0]));
	EXPECT_EQ(readLe32(&blob[116]), 8u); // padH
	EXPECT_EQ(readLe32(&blob[132]), 0u); // pyramidSmooth
	EXPECT_EQ(readLe32(&blob[136]), floatBits(p.nmsOverlap));
	EXPECT_EQ(readLe32(&blob[140]), 1u); // Union
	EXPECT_EQ(readLe32(&blob[144]), 2u); // nFilters
	EXPECT_EQ(readLe32(&blob[148]), 3u); // filterSize
	EXPECT_EQ(readLe32(&blob[152]), 2u); // nTrees
	EXPECT_EQ(readLe32(&blob[156]), 9u); // nodesPerTree
	EXPECT_EQ(readLe32(&blob[160]), 3u); // treeDepth
	EXPECT_EQ(readLe32(&blob[164]), nameLength);
	EXPECT_EQ(std::string(reinterpret_cast<const char *>(&blob[168]), nameLength), m.name);
	for (size_t i = 0; i < weights; i++)
		EXPECT_EQ(readLe32(&blob[168 + nameLength + 4 * i]), static_cast<uint32_t>(m.filters[i]))
			<< "filters " << i;

	const size_t fids = 168 + nameLength + 4 * weights;
	for (size_t i = 0; i < nodes; i++) {
		EXPECT_EQ(readLe32(&blob[fids + 4 * i]), m.fids[i]) << "fids " << i;
		EXPECT_EQ(readLe32(&blob[fids + 4 * nodes + 4 * i]), static_cast<uint32_t>(m.thrs[i]));
		EXPECT_EQ(readLe32(&blob[fids + 8 * nodes + 4 * i]), m.child[i]) << "child " << i;
		EXPECT_EQ(readLe32(&blob[fids + 12 * nodes + 4 * i]), static_cast<uint32_t>(m.hs[i]));
	}
}

TEST(ModelBlob, VersionOneBlobsStillLoadAsModelsWithoutFilters)
{
	for (const Model &m : { test::makeSmallModel(4), [] {
		     Model u = test::makeUnusualModel(); // without its filters: version 1 had none
		     u.params.nFilters = u.params.filterSize = 0;
		     u.filters.clear();
		     for (uint32_t &f : u.fids)
			     f = f ? f + 2560 : 0; // back to ten channels of 2x2 cells: 5120 features
		     return u;
	     }() }) {
		const std::vector<uint8_t> v1 = test::versionOneBlob(m);
		ASSERT_EQ(v1.size() + 8, serializeModel(m).size());
		EXPECT_EQ(readLe32(&v1[8]), 1u);
		EXPECT_EQ(readLe32(&v1[144]), static_cast<uint32_t>(m.nTrees)); // version 1's offsets
		Model loaded;
		const Status s = loadModel(v1.data(), v1.size(), loaded);
		ASSERT_TRUE(s.ok()) << s.message();
		expectSameModel(m, loaded);
		// Written again, it is the version-2 blob.
		EXPECT_EQ(serializeModel(loaded), serializeModel(m));
	}
}

TEST(ModelBlob, SerializeRefusesArraysThatDoNotMatchTheShape)
{
	Model m = test::makeSmallModel();
	m.hs.pop_back();
	EXPECT_TRUE(serializeModel(m).empty());
	m = test::makeSmallModel();
	m.nTrees = -1;
	EXPECT_TRUE(serializeModel(m).empty());
	m = test::makeUnusualModel();
	m.filters.pop_back();
	EXPECT_TRUE(serializeModel(m).empty());
}

TEST(ModelBlob, FeatureCountIsCellsTimesTenChannels)
{
	Model m;
	EXPECT_EQ(m.featureCount(), 32 * 16 * 10); // INRIA: 128x64 pixels, shrink 4
	m.params.shrink = 2;
	m.params.modelDsPadH = 64;
	m.params.modelDsPadW = 32;
	EXPECT_EQ(m.featureCount(), 32 * 16 * 10); // Caltech: 64x32 pixels, shrink 2
	m.params.modelDsPadW = 36;
	EXPECT_EQ(m.featureCount(), 32 * 18 * 10);
	// LDCF: shrink 2 channels, four filters each, resampled to half: 4x4 cells, 40 channels.
	m.params.modelDsPadW = 32;
	m.params.nFilters = 4;
	m.params.filterSize = 5;
	EXPECT_EQ(m.classifierShrink(), 4);
	EXPECT_EQ(m.classifierChannels(), 40);
	EXPECT_EQ(m.featureCount(), 16 * 8 * 40);
	m.params.modelDsPadH = 128;
	m.params.modelDsPadW = 64;
	EXPECT_EQ(m.featureCount(), 32 * 16 * 40); // LdcfInriaDetector: 20480
	m.params.shrink = 0;
	EXPECT_EQ(m.featureCount(), 0);
}

} // namespace
} // namespace calped
