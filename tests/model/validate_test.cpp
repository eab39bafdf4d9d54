// SPDX-License-Identifier: BSD-2-Clause
// Models that serialise with correct checksums but break a rule: validateModel and loadModel
// must both refuse them with the expected code and name the offending field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <calped/model.h>

#include "model_fixture.h"

namespace calped {
namespace {

// Checks validateModel directly and through a blob (serializeModel does not validate).
void expectRejected(const Model &m, ErrorCode code, const std::string &field)
{
	const Status direct = validateModel(m);
	EXPECT_EQ(direct.code(), code) << direct.message();
	EXPECT_NE(std::string(direct.message()).find(field), std::string::npos)
		<< "message should name '" << field << "': " << direct.message();

	const std::vector<uint8_t> blob = serializeModel(m);
	ASSERT_FALSE(blob.empty());
	Model out;
	const Status loaded = loadModel(blob.data(), blob.size(), out);
	EXPECT_EQ(loaded.code(), code) << loaded.message();
	EXPECT_NE(std::string(loaded.message()).find(field), std::string::npos) << loaded.message();
	EXPECT_EQ(out.nTrees, 0);
}

TEST(ModelValidation, SmallAndUnusualModelsAreValid)
{
	EXPECT_TRUE(validateModel(test::makeSmallModel()).ok()) << validateModel(test::makeSmallModel()).message();
	EXPECT_TRUE(validateModel(test::makeUnusualModel()).ok()) << validateModel(test::makeUnusualModel()).message();
}

TEST(ModelValidation, FeatureIndexOutOfRangeNamesFids)
{
	Model m = test::makeSmallModel();
	m.fids[7 + 1] = static_cast<uint32_t>(m.featureCount()); // tree 1, node 1: one past the end
	expectRejected(m, ErrorCode::ModelInvalid, "fids[tree 1, node 1] = 5120");
}

TEST(ModelValidation, LeafFeatureIndexIsBoundedToo)
{
	Model m = test::makeSmallModel();
	m.fids[6] = 0xFFFFFFFFu; // a leaf
	expectRejected(m, ErrorCode::ModelInvalid, "fids[tree 0, node 6]");
}

TEST(ModelValidation, ChildPointingBackToItsParentIsACycleAndNamesChild)
{
	Model m = test::makeSmallModel();
	m.child[2] = 0 + 1; // node 2's children would be nodes 1 and 2: a loop back up
	expectRejected(m, ErrorCode::ModelInvalid, "child[tree 0, node 2] = 1");
	m = test::makeSmallModel();
	m.child[1] = 1; // a node that is its own child
	expectRejected(m, ErrorCode::ModelInvalid, "child[tree 0, node 1] = 1");
}

TEST(ModelValidation, RightChildPastTheTreeNamesChild)
{
	Model m = test::makeSmallModel();
	m.child[7 + 2] = 6; // right child would be node 7, in the next tree
	expectRejected(m, ErrorCode::ModelInvalid, "child[tree 1, node 2] = 6");
}

TEST(ModelValidation, NodeWithTwoParentsNamesChild)
{
	Model m = test::makeSmallModel();
	m.child[2] = 3; // node 2 now shares nodes 3 and 4 with node 1
	expectRejected(m, ErrorCode::ModelInvalid, "already has a parent");
}

// A right-leaning chain: internal nodes 0, 2, 4, ...; the last split's children sit at `depth`.
Model chainModel(int32_t depth)
{
	Model m;
	m.name = "chain";
	m.nTrees = 1;
	m.nodesPerTree = 2 * depth + 1;
	m.treeDepth = depth;
	for (int32_t k = 0; k < m.nodesPerTree; k++) {
		const bool internal = k % 2 == 0 && k < 2 * depth;
		m.child.push_back(internal ? static_cast<uint32_t>(k + 1) : 0);
		m.fids.push_back(internal ? static_cast<uint32_t>(k) : 0);
		m.thrs.push_back(100 * k);
		m.hs.push_back(k);
	}
	return m;
}

TEST(ModelValidation, DepthEightIsAcceptedAndDepthNineNamesTreeDepth)
{
	EXPECT_TRUE(validateModel(chainModel(8)).ok()) << validateModel(chainModel(8)).message();
	expectRejected(chainModel(9), ErrorCode::ModelInvalid, "treeDepth");
	Model m = chainModel(9);
	m.treeDepth = 8; // a field within range, but the walk still finds depth 9
	expectRejected(m, ErrorCode::ModelInvalid, "tree 0 has a leaf at depth 9");
}

TEST(ModelValidation, TreeDepthMustEqualTheDeepestLeaf)
{
	Model m = test::makeSmallModel();
	m.treeDepth = 3;
	expectRejected(m, ErrorCode::ModelInvalid, "treeDepth = 3 but the deepest leaf is at depth 2");
	m.treeDepth = 1;
	expectRejected(m, ErrorCode::ModelInvalid, "treeDepth = 1");
}

TEST(ModelValidation, UnreachableNodesAreAcceptedAndDoNotCountForDepth)
{
	Model m = test::makeSmallModel(2);
	// Tree 1's root becomes a leaf: nodes 1-6 are unreachable, the model stays at depth 2
	// because of tree 0. Then tree 0 too: depth 0.
	m.child[7] = 0;
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
	m.child[0] = 0;
	EXPECT_EQ(validateModel(m).code(), ErrorCode::ModelInvalid);
	m.treeDepth = 0;
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
}

TEST(ModelValidation, ShapeLimitsNameTheirField)
{
	Model m = test::makeSmallModel();
	m.nodesPerTree = 256;
	EXPECT_NE(std::string(validateModel(m).message()).find("nodesPerTree = 256"), std::string::npos);
	m = test::makeSmallModel();
	m.nTrees = 0;
	m.fids.clear(); m.thrs.clear(); m.child.clear(); m.hs.clear();
	expectRejected(m, ErrorCode::ModelInvalid, "nTrees = 0");
	m = test::makeSmallModel();
	m.thrs.pop_back();
	EXPECT_NE(std::string(validateModel(m).message()).find("thrs has 20 entries"), std::string::npos)
		<< validateModel(m).message();
}

TEST(ModelValidation, NameLongerThan256BytesOrWithControlCharactersIsRejected)
{
	Model m = test::makeSmallModel();
	m.name = std::string(256, 'n');
	EXPECT_TRUE(validateModel(m).ok());
	m.name += 'n';
	expectRejected(m, ErrorCode::ModelInvalid, "name length = 257");
	m.name = "tab\there";
	expectRejected(m, ErrorCode::ModelInvalid, "name byte 3");
}

TEST(ModelValidation, LeavesWhoseSumCouldOverflowAnInt32ScoreAreRejected)
{
	Model m = test::makeSmallModel(3);
	for (int32_t &h : m.hs)
		h = std::numeric_limits<int32_t>::max() / 3 + 1; // 3 trees: the sum passes 2^31 - 1
	expectRejected(m, ErrorCode::ModelInvalid, "hs");
	for (int32_t &h : m.hs)
		h = -(std::numeric_limits<int32_t>::max() / 3); // exactly fits
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
}

struct ParamCase {
	const char *field;
	std::function<void(ModelParams &)> edit;
	ErrorCode code;
};

TEST(ModelValidation, EachParameterOutOfRangeIsRejectedAndNamed)
{
	const float nan = std::numeric_limits<float>::quiet_NaN();
	const float inf = std::numeric_limits<float>::infinity();
	const ErrorCode bad = ErrorCode::ModelInvalid, unsupported = ErrorCode::ModelUnsupported;
	const ParamCase cases[] = {
		{ "shrink = 3", [](ModelParams &p) { p.shrink = 3; }, unsupported },
		{ "shrink = 8", [](ModelParams &p) { p.shrink = 8; }, unsupported },
		{ "shrink = 0", [](ModelParams &p) { p.shrink = 0; }, bad },
		{ "nOrients = 8", [](ModelParams &p) { p.nOrients = 8; }, unsupported },
		{ "nOrients = 0", [](ModelParams &p) { p.nOrients = 0; }, bad },
		{ "stride = 6", [](ModelParams &p) { p.stride = 6; }, bad },
		{ "stride = 0", [](ModelParams &p) { p.stride = 0; }, bad },
		{ "modelDsPadH = 130", [](ModelParams &p) { p.modelDsPadH = 130; }, bad },
		{ "modelDsPadW = 0", [](ModelParams &p) { p.modelDsPadW = 0; }, bad },
		{ "modelDsH = 129", [](ModelParams &p) { p.modelDsH = 129; }, bad },
		{ "modelDsW = nan", [nan](ModelParams &p) { p.modelDsW = nan; }, bad },
		{ "modelDsW = 0", [](ModelParams &p) { p.modelDsW = 0; }, bad },
		{ "modelDsH = 1e-30", [](ModelParams &p) { p.modelDsH = 1e-30f; }, bad },
		{ "modelDsW = 3.9", [](ModelParams &p) { p.modelDsW = 3.9f; }, bad },
		{ "cascThr = inf", [inf](ModelParams &p) { p.cascThr = inf; }, bad },
		{ "cascThr = 40000", [](ModelParams &p) { p.cascThr = 40000; }, bad },
		{ "colorSmooth = -1", [](ModelParams &p) { p.colorSmooth = -1; }, bad },
		{ "gradNormRad = 33", [](ModelParams &p) { p.gradNormRad = 33; }, bad },
		{ "gradNormConst = 0", [](ModelParams &p) { p.gradNormConst = 0; }, bad },
		{ "gradNormConst = nan", [nan](ModelParams &p) { p.gradNormConst = nan; }, bad },
		{ "gradColorChn = 4", [](ModelParams &p) { p.gradColorChn = 4; }, bad },
		{ "gradFull = 2", [](ModelParams &p) { p.gradFull = 2; }, bad },
		{ "histBinSize = 0", [](ModelParams &p) { p.histBinSize = 0; }, bad },
		{ "softBin = 2", [](ModelParams &p) { p.softBin = 2; }, bad },
		{ "softBin = -3", [](ModelParams &p) { p.softBin = -3; }, bad },
		{ "nPerOct = 0", [](ModelParams &p) { p.nPerOct = 0; }, bad },
		{ "nPerOct = 65", [](ModelParams &p) { p.nPerOct = 65; }, bad },
		{ "nOctUp = 5", [](ModelParams &p) { p.nOctUp = 5; }, bad },
		{ "nOctUp = -1", [](ModelParams &p) { p.nOctUp = -1; }, bad },
		{ "nApprox = 33", [](ModelParams &p) { p.nApprox = 33; }, bad }, // nPerOct 8
		{ "nApprox = -1", [](ModelParams &p) { p.nApprox = -1; }, bad },
		{ "lambdas[1] = nan", [nan](ModelParams &p) { p.lambdas[1] = nan; }, bad },
		{ "lambdas[2] = 2.5", [](ModelParams &p) { p.lambdas[2] = 2.5f; }, bad },
		{ "padH = 14", [](ModelParams &p) { p.padH = 14; }, bad },
		{ "padW = -4", [](ModelParams &p) { p.padW = -4; }, bad },
		{ "minDsH = 0", [](ModelParams &p) { p.minDsH = 0; }, bad },
		{ "minDsW = inf", [inf](ModelParams &p) { p.minDsW = inf; }, bad },
		{ "pyramidSmooth = 17", [](ModelParams &p) { p.pyramidSmooth = 17; }, bad },
		{ "nmsOverlap = 0", [](ModelParams &p) { p.nmsOverlap = 0; }, bad },
		{ "nmsOverlap = 1.5", [](ModelParams &p) { p.nmsOverlap = 1.5f; }, bad },
		{ "nmsOverlapDenominator = 2",
		  [](ModelParams &p) { p.nmsOverlapDenominator = static_cast<NmsOverlapDenominator>(2); }, bad },
	};
	for (const ParamCase &c : cases) {
		SCOPED_TRACE(c.field);
		Model m = test::makeSmallModel();
		c.edit(m.params);
		expectRejected(m, c.code, c.field);
	}
}

// toolboxCpu is not in the blob (set after loading), so it is checked on the model itself.
TEST(ModelValidation, ToolboxCpuOutsideTheEnumIsRejectedAndNamed)
{
	Model m = test::makeSmallModel();
	m.params.toolboxCpu = ToolboxCpu::AmdEpyc;
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
	m.params.toolboxCpu = static_cast<ToolboxCpu>(2);
	const Status st = validateModel(m);
	EXPECT_EQ(st.code(), ErrorCode::ModelInvalid);
	EXPECT_NE(std::string(st.message()).find("toolboxCpu = 2"), std::string::npos) << st.message();
}

// An LDCF model with its filter shape edited and the weights array resized to match (so
// that the blob can carry it); only the named rule is broken.
Model withFilterShape(int32_t nFilters, int32_t filterSize)
{
	Model m = test::makeUnusualModel();
	m.params.nFilters = nFilters;
	m.params.filterSize = filterSize;
	const int64_t count = int64_t(nFilters) * 10 * filterSize * filterSize;
	m.filters.assign(count > 0 ? size_t(count) : 0, 1000);
	return m;
}

TEST(ModelValidation, EachFilterRuleIsEnforcedAndNamed)
{
	const ErrorCode bad = ErrorCode::ModelInvalid;
	expectRejected(withFilterShape(17, 3), bad, "nFilters = 17");
	expectRejected(withFilterShape(2, 4), bad, "filterSize = 4");
	expectRejected(withFilterShape(2, 17), bad, "filterSize = 17");
	expectRejected(withFilterShape(2, 0), bad, "filterSize = 0");
	expectRejected(withFilterShape(0, 3), bad, "filterSize = 3");
	for (int32_t weight : { 32769, -32769, INT32_MIN, INT32_MAX }) {
		Model m = test::makeUnusualModel();
		m.filters[37] = weight;
		expectRejected(m, bad, "filters[37] = " + std::to_string(weight));
	}
	// The trees read cells of 2 * shrink (here 4 pixels): window and stride in whole cells.
	Model m = test::makeUnusualModel();
	m.params.stride = 6;
	expectRejected(m, bad, "stride = 6");
	m = test::makeUnusualModel();
	m.params.modelDsPadW = 34;
	expectRejected(m, bad, "modelDsPadW = 34");
	// Feature indices are bounded by the filtered channels' count, 16 x 8 cells x 20 channels.
	m = test::makeUnusualModel();
	m.fids[9] = 2560;
	expectRejected(m, bad, "is not below featureCount 2560");
	// Weights without a shape, or of the wrong count, cannot be serialised; validateModel
	// refuses them too.
	m = test::makeUnusualModel();
	m.filters.pop_back();
	EXPECT_EQ(validateModel(m).code(), bad);
	EXPECT_NE(std::string(validateModel(m).message()).find("filters has 179 weights"), std::string::npos)
		<< validateModel(m).message();
	m = test::makeSmallModel();
	m.filters.push_back(0);
	EXPECT_EQ(validateModel(m).code(), bad);
	EXPECT_NE(std::string(validateModel(m).message()).find("nFilters is 0"), std::string::npos)
		<< validateModel(m).message();
}

TEST(ModelValidation, FilterBoundariesAreAccepted)
{
	Model m = withFilterShape(16, 15);
	m.filters.front() = 32768;
	m.filters.back() = -32768;
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
	m = withFilterShape(1, 1);
	for (uint32_t &f : m.fids)
		f %= 1280; // 16 x 8 cells x 10 channels
	EXPECT_TRUE(validateModel(m).ok()) << validateModel(m).message();
}

TEST(ModelValidation, BoundaryParametersAreAccepted)
{
	const std::function<void(ModelParams &)> edits[] = {
		[](ModelParams &p) { p.nApprox = 32; },
		[](ModelParams &p) { p.nmsOverlap = 1.0f; },
		[](ModelParams &p) { p.lambdas[0] = -2.0f; },
		[](ModelParams &p) { p.padH = 0; p.padW = 0; },
		[](ModelParams &p) { p.modelDsH = 128; p.modelDsW = 64; },
		[](ModelParams &p) { p.softBin = -2; },
		[](ModelParams &p) { p.nOctUp = 4; },
		[](ModelParams &p) { p.stride = 12; },
	};
	int i = 0;
	for (const auto &edit : edits) {
		Model m = test::makeSmallModel();
		edit(m.params);
		EXPECT_TRUE(validateModel(m).ok()) << "edit " << i << ": " << validateModel(m).message();
		i++;
	}
}

} // namespace
} // namespace calped
