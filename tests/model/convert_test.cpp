// SPDX-License-Identifier: BSD-2-Clause
// calped-convert end to end on Dollár's released detectors (from ../shared, found through
// CALPED_SHARED_DIR; skipped when absent). The tool's path comes from CALPED_CONVERT.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <calped/model.h>

#include "model/fixed_convert.h"

namespace fs = std::filesystem;

namespace calped {
namespace {

using Table = std::vector<std::vector<std::string>>; // rows of whitespace-separated tokens

std::string env(const char *name)
{
	const char *v = std::getenv(name);
	return v ? v : "";
}

std::string quote(const std::string &s)
{
	std::string q = "'";
	for (char c : s)
		q += c == '\'' ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

std::string readText(const fs::path &path)
{
	std::ifstream in(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Table readTable(const fs::path &path)
{
	Table table;
	std::istringstream lines(readText(path));
	std::string line;
	while (std::getline(lines, line)) {
		std::istringstream words(line);
		table.emplace_back(std::istream_iterator<std::string>(words),
				   std::istream_iterator<std::string>());
	}
	return table;
}

struct RunResult {
	int exitCode = -1; // 128 + signal when killed
	std::string out, err;
};

class ConvertTest : public ::testing::Test
{
protected:
	void SetUp() override
	{
		tool_ = env("CALPED_CONVERT");
		ASSERT_FALSE(tool_.empty()) << "CALPED_CONVERT is not set (tests/model/meson.build sets it)";
		const std::string shared = env("CALPED_SHARED_DIR");
		models_ = fs::path(shared) / "models" / "dollar-toolbox";
		reference_ = fs::path(shared) / "reference" / "dollar-toolbox-pets";
		if (shared.empty() || !fs::exists(models_ / "AcfInriaDetector.mat"))
			GTEST_SKIP() << "../shared not found (CALPED_SHARED_DIR='" << shared
				     << "'): the converter tests need Dollar's .mat models";
		std::string pattern = (fs::temp_directory_path() / "calped-convert-XXXXXX").string();
		ASSERT_NE(mkdtemp(pattern.data()), nullptr);
		tmp_ = pattern;
	}

	void TearDown() override
	{
		std::error_code ec;
		if (!tmp_.empty())
			fs::remove_all(tmp_, ec);
	}

	RunResult run(const std::vector<std::string> &args)
	{
		std::string cmd = quote(tool_);
		for (const std::string &a : args)
			cmd += " " + quote(a);
		const fs::path out = tmp_ / "stdout.txt", err = tmp_ / "stderr.txt";
		cmd += " >" + quote(out.string()) + " 2>" + quote(err.string());
		const int status = std::system(cmd.c_str());
		RunResult r;
		if (WIFEXITED(status))
			r.exitCode = WEXITSTATUS(status);
		else if (WIFSIGNALED(status))
			r.exitCode = 128 + WTERMSIG(status);
		r.out = readText(out);
		r.err = readText(err);
		return r;
	}

	// A failed run: exit code 1, exactly one line on stderr containing `needle`, no output.
	void expectOneLineFailure(const RunResult &r, const std::string &needle, const fs::path &output)
	{
		EXPECT_EQ(r.exitCode, 1) << r.err;
		EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr: " << r.err;
		EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
		EXPECT_FALSE(fs::exists(output)) << "a failed conversion left " << output;
	}

	Model load(const fs::path &blobPath)
	{
		const std::string bytes = readText(blobPath);
		Model m;
		const Status s = loadModel(reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size(), m);
		EXPECT_TRUE(s.ok()) << s.message();
		return m;
	}

	std::string tool_;
	fs::path models_, reference_, tmp_;
};

TEST_F(ConvertTest, InriaDumpedArraysEqualTheReferenceClfFiles)
{
	const RunResult r = run({ "--dump-arrays", (tmp_ / "dump").string(),
				  (models_ / "AcfInriaDetector.mat").string(), (tmp_ / "inria.cpm").string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	const char *const integers[] = { "fids", "child", "depth" };
	const char *const floats[] = { "thrs", "hs", "weights" };
	for (const char *name : integers) {
		SCOPED_TRACE(name);
		const Table got = readTable(tmp_ / "dump" / (std::string(name) + ".txt"));
		const Table want = readTable(reference_ / "clf" / (std::string(name) + ".txt"));
		ASSERT_EQ(want.size(), 7u);
		ASSERT_EQ(got.size(), want.size());
		for (size_t row = 0; row < want.size(); row++) {
			ASSERT_EQ(want[row].size(), 2048u);
			ASSERT_EQ(got[row].size(), want[row].size()) << "row " << row;
			for (size_t col = 0; col < want[row].size(); col++)
				ASSERT_EQ(std::stoll(got[row][col]), std::stoll(want[row][col]))
					<< "row " << row << " col " << col;
		}
	}
	for (const char *name : floats) {
		SCOPED_TRACE(name);
		const Table got = readTable(tmp_ / "dump" / (std::string(name) + ".txt"));
		const Table want = readTable(reference_ / "clf" / (std::string(name) + ".txt"));
		ASSERT_EQ(got.size(), want.size());
		ASSERT_EQ(want.size(), 7u);
		for (size_t row = 0; row < want.size(); row++) {
			ASSERT_EQ(got[row].size(), want[row].size()) << "row " << row;
			for (size_t col = 0; col < want[row].size(); col++)
				ASSERT_EQ(std::stof(got[row][col]), std::stof(want[row][col]))
					<< "row " << row << " col " << col;
		}
	}
}

TEST_F(ConvertTest, InriaBlobCarriesTheModelOptions)
{
	const fs::path blob = tmp_ / "inria.cpm";
	const RunResult r = run({ (models_ / "AcfInriaDetector.mat").string(), blob.string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_NE(r.out.find("AcfInriaDetector: 2048 trees x 7 nodes, depth 2"), std::string::npos) << r.out;
	const Model m = load(blob);
	const ModelParams &p = m.params;
	EXPECT_EQ(m.name, "AcfInriaDetector");
	EXPECT_EQ(m.nTrees, 2048);
	EXPECT_EQ(m.nodesPerTree, 7);
	EXPECT_EQ(m.treeDepth, 2);
	EXPECT_EQ(p.modelDsH, 100.0f);
	EXPECT_EQ(p.modelDsW, 41.0f);
	EXPECT_EQ(p.modelDsPadH, 128);
	EXPECT_EQ(p.modelDsPadW, 64);
	EXPECT_EQ(p.stride, 4);
	EXPECT_EQ(p.cascThr, -1.0f);
	EXPECT_EQ(p.shrink, 4);
	EXPECT_EQ(p.colorSmooth, 1);
	EXPECT_EQ(p.gradNormRad, 5);
	EXPECT_EQ(p.gradNormConst, 0.005f);
	EXPECT_EQ(p.gradColorChn, 0);
	EXPECT_EQ(p.gradFull, 0);
	EXPECT_EQ(p.histBinSize, 4); // empty binSize in the .mat means shrink
	EXPECT_EQ(p.nOrients, 6);
	EXPECT_EQ(p.softBin, 0);
	EXPECT_EQ(p.nPerOct, 8);
	EXPECT_EQ(p.nOctUp, 0);
	EXPECT_EQ(p.nApprox, 7);
	EXPECT_EQ(p.lambdas[0], 0.0f);
	EXPECT_EQ(p.lambdas[1], 0.11579f);
	EXPECT_EQ(p.lambdas[2], 0.11579f);
	EXPECT_EQ(p.padH, 16);
	EXPECT_EQ(p.padW, 12);
	EXPECT_EQ(p.minDsH, 100.0f);
	EXPECT_EQ(p.minDsW, 41.0f);
	EXPECT_EQ(p.pyramidSmooth, 1);
	EXPECT_EQ(p.nmsOverlap, 0.65f);
	EXPECT_EQ(p.nmsOverlapDenominator, NmsOverlapDenominator::Min);
}

TEST_F(ConvertTest, InriaTreesFollowTheFixedPointConversionRules)
{
	const fs::path blob = tmp_ / "inria.cpm";
	ASSERT_EQ(run({ (models_ / "AcfInriaDetector.mat").string(), blob.string() }).exitCode, 0);
	const Model m = load(blob);
	const Table fids = readTable(reference_ / "clf" / "fids.txt");
	const Table thrs = readTable(reference_ / "clf" / "thrs.txt");
	const Table child = readTable(reference_ / "clf" / "child.txt");
	const Table hs = readTable(reference_ / "clf" / "hs.txt");
	ASSERT_EQ(m.fids.size(), 7u * 2048u);
	size_t internal = 0;
	for (size_t tree = 0; tree < 2048; tree++) {
		for (size_t node = 0; node < 7; node++) {
			const size_t i = tree * 7 + node; // Model: node-major per tree
			const float thr = std::stof(thrs[node][tree]);
			const float h = std::stof(hs[node][tree]);
			const long long c = std::stoll(child[node][tree]);
			ASSERT_EQ(m.fids[i], std::stoull(fids[node][tree])) << "tree " << tree << " node " << node;
			ASSERT_EQ(m.thrs[i], thresholdToFixed(thr)) << "tree " << tree << " node " << node;
			// Written out independently of leafValueToFixed: nearest multiple of 2^-16.
			ASSERT_EQ(m.hs[i], static_cast<int32_t>(std::llround(static_cast<double>(h) * 65536.0)));
			ASSERT_EQ(m.child[i], c == 0 ? 0u : static_cast<uint32_t>(c - 1));
			internal += c != 0;
		}
	}
	EXPECT_EQ(internal, 3u * 2048u); // depth-2 trees: 3 splits, 4 leaves each
	// Spot check against numbers worked out by hand from the reference files:
	// tree 0's root: fid 2328, thr 0.19096832 -> ceil(3128.85...) = 3129, toolbox child 2 -> 1.
	EXPECT_EQ(m.fids[0], 2328u);
	EXPECT_EQ(m.thrs[0], 3129);
	EXPECT_EQ(m.child[0], 1u);
}

TEST_F(ConvertTest, CaltechModelWithFractionalWindowConvertsAndLoads)
{
	const fs::path blob = tmp_ / "caltech.cpm";
	const RunResult r = run({ (models_ / "AcfCaltech+Detector.mat").string(), blob.string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	std::cout << "  calped-convert: " << r.out;
	const Model m = load(blob);
	const ModelParams &p = m.params;
	std::cout << "  Caltech window " << p.modelDsH << "x" << p.modelDsW << " in " << p.modelDsPadH
		  << "x" << p.modelDsPadW << ", shrink " << p.shrink << ", stride " << p.stride
		  << ", pad " << p.padH << "x" << p.padW << ", softBin " << p.softBin << ", colorSmooth "
		  << p.colorSmooth << ", lambdas " << p.lambdas[0] << " " << p.lambdas[1] << " "
		  << p.lambdas[2] << ", " << m.nTrees << " trees of depth " << m.treeDepth << "\n";
	EXPECT_EQ(m.name, "AcfCaltech+Detector");
	EXPECT_EQ(p.modelDsH, 50.0f);
	EXPECT_EQ(p.modelDsW, 20.5f);
	EXPECT_EQ(p.modelDsPadH, 64);
	EXPECT_EQ(p.modelDsPadW, 32);
	EXPECT_EQ(p.shrink, 2);
	EXPECT_EQ(p.softBin, 1);
	EXPECT_EQ(m.nTrees, 4096);
	EXPECT_EQ(m.nodesPerTree, 63);
	EXPECT_EQ(m.treeDepth, 5); // the .mat says 0: its trees are not all complete
	EXPECT_EQ(m.featureCount(), 5120);
}

TEST_F(ConvertTest, NameOptionIsStoredInTheBlob)
{
	const fs::path blob = tmp_ / "named.cpm";
	const RunResult r = run({ "--name", "inria-test", (models_ / "AcfInriaDetector.mat").string(),
				  blob.string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	EXPECT_EQ(load(blob).name, "inria-test");
}

// The blob's node arrays against the arrays dumped straight from the .mat (--dump-arrays):
// every fid copied, every threshold through thresholdToFixed, every leaf rounded to Q16,
// every child c stored as c - 1.
void expectBlobFollowsTheMatArrays(const Model &m, const fs::path &dump, size_t nodes, size_t trees)
{
	const Table fids = readTable(dump / "fids.txt");
	const Table thrs = readTable(dump / "thrs.txt");
	const Table child = readTable(dump / "child.txt");
	const Table hs = readTable(dump / "hs.txt");
	ASSERT_EQ(fids.size(), nodes);
	ASSERT_EQ(m.fids.size(), nodes * trees);
	for (size_t node = 0; node < nodes; node++) {
		ASSERT_EQ(fids[node].size(), trees);
		ASSERT_EQ(thrs[node].size(), trees);
		for (size_t tree = 0; tree < trees; tree++) {
			const size_t i = tree * nodes + node;
			const long long c = std::stoll(child[node][tree]);
			ASSERT_EQ(m.fids[i], std::stoull(fids[node][tree])) << "tree " << tree << " node " << node;
			// The dump prints single-precision values with %.9g: read back as floats, exact.
			ASSERT_EQ(m.thrs[i], thresholdToFixed(std::stof(thrs[node][tree])))
				<< "tree " << tree << " node " << node;
			ASSERT_EQ(m.hs[i], static_cast<int32_t>(std::llround(double(std::stof(hs[node][tree])) * 65536.0)))
				<< "tree " << tree << " node " << node;
			ASSERT_EQ(m.child[i], c == 0 ? 0u : static_cast<uint32_t>(c - 1));
		}
	}
}

TEST_F(ConvertTest, CaltechTreesEqualTheMatArrays)
{
	const fs::path blob = tmp_ / "caltech.cpm";
	const RunResult r = run({ "--dump-arrays", (tmp_ / "dump").string(),
				  (models_ / "AcfCaltech+Detector.mat").string(), blob.string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	const Model m = load(blob);
	expectBlobFollowsTheMatArrays(m, tmp_ / "dump", 63, 4096);
	EXPECT_EQ(m.params.nFilters, 0);
	EXPECT_TRUE(m.filters.empty());
}

TEST_F(ConvertTest, LdcfModelConvertsWithItsFilters)
{
	const fs::path blob = tmp_ / "ldcf.cpm";
	const RunResult r = run({ "--dump-arrays", (tmp_ / "dump").string(),
				  (models_ / "LdcfInriaDetector.mat").string(), blob.string() });
	ASSERT_EQ(r.exitCode, 0) << r.err;
	std::cout << "  calped-convert: " << r.out;
	EXPECT_NE(r.out.find("LdcfInriaDetector: 1567 trees x 15 nodes, depth 3, window 100x41 in "
			     "128x64, shrink 2, stride 4, 4 5x5 filters per channel"),
		  std::string::npos) << r.out;
	const Model m = load(blob);
	const ModelParams &p = m.params;
	// reference/dollar-toolbox-pets/LdcfInriaDetector/opts.txt
	EXPECT_EQ(m.name, "LdcfInriaDetector");
	EXPECT_EQ(p.shrink, 2);
	EXPECT_EQ(m.classifierShrink(), 4);
	EXPECT_EQ(m.classifierChannels(), 40);
	EXPECT_EQ(m.featureCount(), 32 * 16 * 40);
	EXPECT_EQ(p.modelDsPadH, 128);
	EXPECT_EQ(p.modelDsPadW, 64);
	EXPECT_EQ(p.stride, 4);
	EXPECT_EQ(p.colorSmooth, 1);
	EXPECT_EQ(p.softBin, 0);
	EXPECT_EQ(p.padH, 14);
	EXPECT_EQ(p.padW, 12);
	EXPECT_EQ(p.nPerOct, 8);
	EXPECT_EQ(p.nOctUp, 0);
	EXPECT_EQ(p.nApprox, 7);
	EXPECT_EQ(p.lambdas[0], 0.0f);
	EXPECT_EQ(p.lambdas[1], 0.11152f);
	EXPECT_EQ(p.lambdas[2], 0.11152f);
	EXPECT_EQ(m.nTrees, 1567);
	EXPECT_EQ(m.nodesPerTree, 15);
	EXPECT_EQ(m.treeDepth, 3);
	expectBlobFollowsTheMatArrays(m, tmp_ / "dump", 15, 1567);

	// The filters against the toolbox's own float32 dump, Matlab order [5 5 10 4].
	ASSERT_EQ(p.nFilters, 4);
	ASSERT_EQ(p.filterSize, 5);
	const std::string bytes = readText(reference_ / "LdcfInriaDetector" / "filters_f32.bin");
	ASSERT_EQ(bytes.size(), 4u * 1000u);
	ASSERT_EQ(m.filters.size(), 1000u);
	int32_t largest = 0;
	for (size_t j = 0; j < 4; j++)
		for (size_t c = 0; c < 10; c++)
			for (size_t x = 0; x < 5; x++)
				for (size_t y = 0; y < 5; y++) {
					float v;
					std::memcpy(&v, bytes.data() + 4 * (y + 5 * (x + 5 * (c + 10 * j))), 4);
					const int32_t want = static_cast<int32_t>(std::llround(double(v) * 32768.0));
					ASSERT_EQ(m.filters[((j * 10 + c) * 5 + y) * 5 + x], want)
						<< "filter " << j << " channel " << c << " row " << y << " col " << x;
					largest = std::max(largest, std::abs(want));
				}
	EXPECT_GT(largest, 10000); // the weights are really there (|w| up to 0.365)
}

TEST_F(ConvertTest, MissingInputFileFailsWithOneLineMessage)
{
	const fs::path blob = tmp_ / "missing.cpm";
	const RunResult r = run({ (tmp_ / "no-such-model.mat").string(), blob.string() });
	expectOneLineFailure(r, "no-such-model.mat", blob);
	EXPECT_NE(r.err.find("IoError"), std::string::npos) << r.err;
}

TEST_F(ConvertTest, TextFileInsteadOfMatFailsWithOneLineMessage)
{
	const fs::path text = tmp_ / "notes.mat";
	std::ofstream(text) << "this is not a MAT file\nat all\n";
	const fs::path blob = tmp_ / "text.cpm";
	const RunResult r = run({ text.string(), blob.string() });
	expectOneLineFailure(r, "not a MAT file", blob);
}

TEST_F(ConvertTest, TruncatedMatFileFailsCleanly)
{
	const std::string whole = readText(models_ / "AcfInriaDetector.mat");
	const fs::path cut = tmp_ / "cut.mat";
	for (size_t length : { size_t(0), size_t(100), size_t(128), size_t(1000), size_t(60000) }) {
		SCOPED_TRACE(length);
		std::ofstream(cut, std::ios::binary).write(whole.data(), static_cast<std::streamsize>(length));
		const fs::path blob = tmp_ / "cut.cpm";
		const RunResult r = run({ cut.string(), blob.string() });
		expectOneLineFailure(r, "calped-convert: ", blob);
	}
}

// A changed byte inside the compressed variable, or a cut at its end: matio read what it
// needed and the model converted "successfully" into another one. Now zlib's checksum and
// the element lengths are checked first (tools/convert/mat_integrity.h).
TEST_F(ConvertTest, ChangedOrTruncatedMatIsRefusedNotConverted)
{
	const std::string whole = readText(models_ / "AcfInriaDetector.mat");
	ASSERT_GT(whole.size(), 60000u);
	const fs::path bad = tmp_ / "bad.mat";
	const fs::path blob = tmp_ / "bad.cpm";
	for (size_t at : { size_t(5000), size_t(50000), whole.size() - 3 }) {
		SCOPED_TRACE(at);
		std::string changed = whole;
		changed[at] = static_cast<char>(changed[at] ^ 0x10);
		std::ofstream(bad, std::ios::binary).write(changed.data(), static_cast<std::streamsize>(changed.size()));
		const RunResult r = run({ bad.string(), blob.string() });
		expectOneLineFailure(r, "ParseError", blob);
		EXPECT_NE(r.err.find("compressed variable"), std::string::npos) << r.err;
	}
	std::ofstream(bad, std::ios::binary).write(whole.data(), static_cast<std::streamsize>(whole.size() - 1));
	const RunResult cut = run({ bad.string(), blob.string() });
	expectOneLineFailure(cut, "truncated", blob);
}

TEST_F(ConvertTest, BadUsageIsOneLineAndExitsWithTwo)
{
	EXPECT_EQ(run({}).exitCode, 2);
	RunResult r = run({ "only-one.mat" });
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_EQ(r.err, "calped-convert: expected two arguments, IN.mat and OUT.cpm, got 1 (try --help)\n");
	r = run({ "--bogus", "a.mat", "b.cpm" });
	EXPECT_EQ(r.exitCode, 2);
	EXPECT_EQ(r.err, "calped-convert: unknown option '--bogus' (try --help)\n");
	r = run({ "--help" });
	EXPECT_EQ(r.exitCode, 0);
	EXPECT_NE(r.out.find("usage: calped-convert"), std::string::npos) << r.out;
}

} // namespace
} // namespace calped
