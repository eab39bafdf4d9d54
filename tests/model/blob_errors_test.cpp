// SPDX-License-Identifier: BSD-2-Clause
// loadModel on damaged, truncated and foreign input: always an error with the right code,
// never a crash, and `out` left empty.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include <calped/model.h>

#include "model/blob_format.h"
#include "model/byte_io.h"
#include "model_fixture.h"

namespace calped {
namespace {

Status load(const std::vector<uint8_t> &blob, Model &out)
{
	return loadModel(blob.empty() ? nullptr : blob.data(), blob.size(), out);
}

void expectEmpty(const Model &m)
{
	EXPECT_TRUE(m.name.empty());
	EXPECT_EQ(m.nTrees, 0);
	EXPECT_EQ(m.nodesPerTree, 0);
	EXPECT_TRUE(m.fids.empty() && m.thrs.empty() && m.child.empty() && m.hs.empty());
}

TEST(ModelBlobErrors, EveryTruncationLengthIsModelTruncated)
{
	const std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
	for (size_t length = 0; length < blob.size(); length++) {
		Model out = test::makeSmallModel();
		const Status s = loadModel(blob.data(), length, out);
		ASSERT_EQ(s.code(), ErrorCode::ModelTruncated)
			<< "length " << length << ": " << s.message();
		expectEmpty(out);
	}
}

TEST(ModelBlobErrors, EveryHeaderBitFlipIsRejectedWithTheCodeOfItsField)
{
	const std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
	for (size_t bit = 0; bit < 8 * blob::kHeaderSize; bit++) {
		std::vector<uint8_t> bad = blob;
		bad[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
		Model out;
		const Status s = load(bad, out);
		const size_t byte = bit / 8;
		ErrorCode expected = ErrorCode::ModelChecksum; // sizes and CRCs: header CRC
		if (byte < 8)
			expected = ErrorCode::ModelBadMagic;
		else if (byte < 12)
			expected = ErrorCode::ModelBadVersion;
		EXPECT_EQ(s.code(), expected) << "header bit " << bit << ": " << s.message();
		expectEmpty(out);
	}
}

TEST(ModelBlobErrors, RandomPayloadBitFlipsFailTheChecksum)
{
	const std::vector<uint8_t> blob = serializeModel(test::makeSmallModel(20));
	std::mt19937 rng(1234);
	std::uniform_int_distribution<size_t> pick(8 * blob::kHeaderSize, 8 * blob.size() - 1);
	for (int i = 0; i < 4000; i++) {
		std::vector<uint8_t> bad = blob;
		const size_t bit = pick(rng);
		bad[bit / 8] ^= static_cast<uint8_t>(1u << (bit % 8));
		Model out;
		const Status s = load(bad, out);
		ASSERT_EQ(s.code(), ErrorCode::ModelChecksum) << "payload bit " << bit << ": " << s.message();
	}
}

TEST(ModelBlobErrors, RandomGarbageOfManySizesIsRejected)
{
	std::mt19937 rng(99);
	for (size_t size = 0; size < 2000; size += 1 + size / 8) {
		for (int round = 0; round < 20; round++) {
			std::vector<uint8_t> junk(size);
			for (uint8_t &b : junk)
				b = static_cast<uint8_t>(rng());
			// Half of them start like a blob, so the later checks run too.
			if (round % 2 && size >= 12) {
				std::copy(blob::kMagic, blob::kMagic + 8, junk.begin());
				writeLe32(junk.data() + 8, blob::kVersion);
			}
			Model out;
			const Status s = load(junk, out);
			ASSERT_FALSE(s.ok()) << "size " << size;
			expectEmpty(out);
		}
	}
}

TEST(ModelBlobErrors, RandomPayloadBehindAValidHeaderNeverLoads)
{
	// Valid header and checksums around random payload bytes: the parser and the
	// validator (not the CRC) must turn every one of them down.
	std::mt19937 rng(7);
	for (size_t size = 0; size < 4096; size += 1 + size / 4) {
		std::vector<uint8_t> blob(blob::kHeaderSize + size);
		std::copy(blob::kMagic, blob::kMagic + 8, blob.begin());
		writeLe32(blob.data() + 8, blob::kVersion);
		writeLe32(blob.data() + 12, blob::kHeaderSize);
		for (size_t i = blob::kHeaderSize; i < blob.size(); i++)
			blob[i] = static_cast<uint8_t>(rng());
		test::refreshChecksums(blob);
		Model out;
		const Status s = load(blob, out);
		ASSERT_EQ(s.code(), ErrorCode::ModelInvalid) << "payload size " << size << ": " << s.message();
	}
}

TEST(ModelBlobErrors, MutatedNodesWithFixedChecksumsLoadOnlyWhenValid)
{
	// Random edits of the node arrays, checksums recomputed: whatever loads must also pass
	// validateModel, and nothing may crash.
	const Model base = test::makeSmallModel(4);
	const std::vector<uint8_t> blob = serializeModel(base);
	const size_t arrays = 160 + base.name.size();
	std::mt19937 rng(4321);
	std::uniform_int_distribution<size_t> pick(arrays, blob.size() - 1);
	int loaded = 0, rejected = 0;
	for (int i = 0; i < 3000; i++) {
		std::vector<uint8_t> bad = blob;
		for (int edits = 1 + i % 3; edits > 0; edits--)
			bad[pick(rng)] = static_cast<uint8_t>(rng());
		test::refreshChecksums(bad);
		Model out;
		const Status s = load(bad, out);
		if (s.ok()) {
			loaded++;
			EXPECT_TRUE(validateModel(out).ok());
		} else {
			rejected++;
			EXPECT_EQ(s.code(), ErrorCode::ModelInvalid) << s.message();
			expectEmpty(out);
		}
	}
	// Both outcomes must occur, or the test is not exercising what it claims.
	EXPECT_GT(loaded, 0);
	EXPECT_GT(rejected, 0);
}

TEST(ModelBlobErrors, PngFileIsBadMagic)
{
	const std::vector<uint8_t> png = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',
					   0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 1, 0 };
	Model out;
	const Status s = load(png, out);
	EXPECT_EQ(s.code(), ErrorCode::ModelBadMagic) << s.message();
	EXPECT_NE(std::string(s.message()).find("89 50 4E 47"), std::string::npos) << s.message();
}

TEST(ModelBlobErrors, EmptyInputIsTruncatedAndNullDataIsInvalidArgument)
{
	Model out;
	EXPECT_EQ(loadModel(nullptr, 0, out).code(), ErrorCode::ModelTruncated);
	const uint8_t byte = 'C';
	EXPECT_EQ(loadModel(&byte, 0, out).code(), ErrorCode::ModelTruncated);
	EXPECT_EQ(loadModel(nullptr, 100, out).code(), ErrorCode::InvalidArgument);
}

TEST(ModelBlobErrors, NewerOrOlderVersionIsBadVersion)
{
	for (uint32_t version : { 3u, 0u, 0x80000002u }) {
		std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
		writeLe32(blob.data() + 8, version);
		test::refreshChecksums(blob);
		Model out;
		const Status s = load(blob, out);
		EXPECT_EQ(s.code(), ErrorCode::ModelBadVersion);
		EXPECT_NE(std::string(s.message()).find("version = " + std::to_string(version)),
			  std::string::npos) << s.message();
		expectEmpty(out);
	}
}

TEST(ModelBlobErrors, VersionOneBlobsAreCheckedLikeVersionTwo)
{
	// Every truncation of a version-1 blob is still ModelTruncated, and a version-1 header in
	// front of a version-2 payload (8 bytes too long for version 1's layout) is refused.
	const std::vector<uint8_t> v1 = test::versionOneBlob(test::makeSmallModel());
	for (size_t length = 0; length < v1.size(); length++) {
		Model out;
		ASSERT_EQ(loadModel(v1.data(), length, out).code(), ErrorCode::ModelTruncated) << length;
	}
	std::vector<uint8_t> mixed = serializeModel(test::makeSmallModel());
	writeLe32(mixed.data() + 8, 1);
	test::refreshChecksums(mixed);
	Model out;
	EXPECT_EQ(load(mixed, out).code(), ErrorCode::ModelInvalid);
	expectEmpty(out);
}

TEST(ModelBlobErrors, FilterShapeBeyondThePayloadIsInvalidWithoutAHugeAllocation)
{
	// nFilters and filterSize are checked before the weights are sized.
	for (const auto &shape : { std::pair<int32_t, int32_t>{ 16, 15 }, { 17, 5 }, { 4, 16 },
				   { -1, 5 }, { 4, -3 } }) {
		std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
		writeLe32(blob.data() + 144, static_cast<uint32_t>(shape.first));
		writeLe32(blob.data() + 148, static_cast<uint32_t>(shape.second));
		test::refreshChecksums(blob);
		Model out;
		const Status s = load(blob, out);
		EXPECT_EQ(s.code(), ErrorCode::ModelInvalid) << s.message();
		EXPECT_TRUE(std::string(s.message()).find("filter") != std::string::npos ||
			    std::string(s.message()).find("nFilters") != std::string::npos)
			<< s.message();
		expectEmpty(out);
	}
}

TEST(ModelBlobErrors, TrailingBytesAfterThePayloadAreRejected)
{
	std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
	blob.push_back(0);
	Model out;
	const Status s = load(blob, out);
	EXPECT_EQ(s.code(), ErrorCode::ModelInvalid);
	EXPECT_NE(std::string(s.message()).find("trailing"), std::string::npos) << s.message();
	// The same extra byte declared as part of the payload: the arrays no longer fit.
	test::refreshChecksums(blob);
	EXPECT_EQ(load(blob, out).code(), ErrorCode::ModelInvalid);
}

TEST(ModelBlobErrors, PayloadCutShortWithConsistentHeaderIsInvalid)
{
	std::vector<uint8_t> blob = serializeModel(test::makeSmallModel());
	blob.resize(blob.size() - 4);
	test::refreshChecksums(blob);
	Model out;
	const Status s = load(blob, out);
	EXPECT_EQ(s.code(), ErrorCode::ModelInvalid);
	EXPECT_NE(std::string(s.message()).find("node arrays"), std::string::npos) << s.message();
}

TEST(ModelBlobErrors, FailedLoadEmptiesAPreviouslyLoadedModel)
{
	Model out = test::makeSmallModel();
	const std::vector<uint8_t> junk(64, 0xAB);
	EXPECT_FALSE(load(junk, out).ok());
	expectEmpty(out);
}

} // namespace
} // namespace calped
