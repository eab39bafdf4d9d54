// SPDX-License-Identifier: BSD-2-Clause
// Every program's command line, through the one parser of tools/common: --version, --help,
// "--opt value" and "--opt=value" alike, and usage errors that name the flag as written,
// are one line and exit 2.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <calped/version.h>

#include "process.h"

namespace fs = std::filesystem;
using calped::test::ProcessResult;
using calped::test::runProcess;
using calped::test::splitLines;

// name -> path, from --program=NAME=PATH (the programs this build has).
std::map<std::string, std::string> gPrograms;

namespace {

class Programs : public ::testing::Test
{
protected:
	void SetUp() override
	{
		dir_ = fs::temp_directory_path() / ("calped-programs-" + std::to_string(::getpid()));
		fs::create_directories(dir_);
	}
	void TearDown() override
	{
		std::error_code ec;
		fs::remove_all(dir_, ec);
	}
	ProcessResult run(const std::string &name, const std::vector<std::string> &args)
	{
		return runProcess(gPrograms.at(name), args, dir_.string());
	}
	bool has(const std::string &name) const { return gPrograms.count(name) != 0; }

	// One line on stderr, "NAME: " + message containing `part`, exit status `code`.
	void expectError(const std::string &name, const ProcessResult &r, int code, const std::string &part)
	{
		ASSERT_TRUE(r.exited) << name << " killed by signal " << r.signal;
		EXPECT_EQ(r.exitCode, code) << name << ": " << r.err;
		const std::vector<std::string> lines = splitLines(r.err);
		ASSERT_EQ(lines.size(), 1u) << name << ": " << r.err;
		EXPECT_EQ(lines[0].rfind(name + ": ", 0), 0u) << lines[0];
		EXPECT_NE(lines[0].find(part), std::string::npos) << lines[0];
	}

	// The arguments with "FLAG VALUE" and with "FLAG=VALUE" at the end.
	static std::pair<std::vector<std::string>, std::vector<std::string>>
	bothWays(std::vector<std::string> before, const char *flag, const char *value)
	{
		std::vector<std::string> joined = before;
		before.push_back(flag);
		before.push_back(value);
		joined.push_back(std::string(flag) + "=" + value);
		return { before, joined };
	}

	fs::path dir_;
};

TEST_F(Programs, AllAreHere)
{
	// The programs every tools build has (calped-convert also needs libmatio, which a
	// cross build may lack: it is tested wherever it is built).
	for (const char *name : { "calped-detect", "calped-eval", "calped-calibrate", "calped-play" })
		EXPECT_TRUE(has(name)) << name << " not passed to the test (tests/tools/meson.build)";
}

TEST_F(Programs, VersionAndHelp)
{
	for (const auto &p : gPrograms) {
		ProcessResult r = run(p.first, { "--version" });
		ASSERT_TRUE(r.exited) << p.first;
		EXPECT_EQ(r.exitCode, 0) << p.first << ": " << r.err;
		EXPECT_EQ(r.out, p.first + " " + CALPED_VERSION + "\n") << p.first;
		EXPECT_TRUE(r.err.empty()) << p.first << ": " << r.err;
		for (const char *help : { "--help", "-h" }) {
			r = run(p.first, { help });
			EXPECT_EQ(r.exitCode, 0) << p.first << " " << help << ": " << r.err;
			EXPECT_NE(r.out.find("usage: " + p.first), std::string::npos) << p.first << ": " << r.out;
			EXPECT_NE(r.out.find("--version"), std::string::npos) << p.first << ": " << r.out;
		}
	}
}

TEST_F(Programs, UnknownOptionIsNamedAsWritten)
{
	for (const auto &p : gPrograms) {
		expectError(p.first, run(p.first, { "--bogus" }), 2, "unknown option '--bogus' (try --help)");
		expectError(p.first, run(p.first, { "--bogus=3" }), 2, "unknown option '--bogus' (try --help)");
		// A flag given a value, a value option without one.
		expectError(p.first, run(p.first, { "--help=1" }), 2, "--help takes no value");
	}
	expectError("calped-eval", run("calped-eval", { "--gt" }), 2, "--gt needs a value");
	expectError("calped-detect", run("calped-detect", { "x.png", "--model" }), 2, "--model needs a value");
}

// A bad value, given either way, is the same usage error naming the flag.
struct BadValue {
	const char *program;
	std::vector<std::string> before; // other arguments
	const char *flag;
	const char *value;
	const char *message; // expected after "PROGRAM: "
};

TEST_F(Programs, BadValuesEitherWay)
{
	const std::vector<BadValue> cases = {
		{ "calped-detect", { "--model", "m", "x.png" }, "--resize", "x",
		  "--resize: expected a number > 0 and <= 8, got 'x'" },
		{ "calped-detect", { "--model", "m", "x.png" }, "--method", "fast",
		  "--method: expected generic or calibrated, got 'fast'" },
		{ "calped-eval", { "--frames", "f", "--gt", "g", "--model", "m" }, "--jobs", "0",
		  "--jobs: expected a whole number from 1 to 64, got '0'" },
		{ "calped-eval", { "--frames", "f", "--gt", "g", "--model", "m" }, "--levels", "octaves",
		  "--levels: expected placed or toolbox, got 'octaves'" },
		{ "calped-calibrate", { "x.csv" }, "--unit", "ft", "--unit: expected mm, cm or m, got 'ft'" },
		{ "calped-play", { "--input", "x", "--model", "m" }, "--fps", "0",
		  "--fps: expected a number > 0 and <= 1000, got '0'" },
		{ "calped-play", { "--input", "x", "--model", "m" }, "--resize-at", "top",
		  "--resize-at: expected pyramid or frame, got 'top'" },
		{ "calped-aravis", { "--model", "m" }, "--buffers", "1",
		  "--buffers: expected a whole number from 2 to 64, got '1'" },
		{ "calped-libcamera", { "--model", "m" }, "--buffers", "1",
		  "--buffers: expected a whole number from 2 to 16, got '1'" },
	};
	for (const BadValue &c : cases) {
		if (!has(c.program))
			continue;
		const auto args = bothWays(c.before, c.flag, c.value);
		expectError(c.program, run(c.program, args.first), 2, c.message);
		expectError(c.program, run(c.program, args.second), 2, c.message);
	}
}

// A good value, given either way, gets past parsing to the same runtime error (exit 1):
// had "--opt=value" not been split, the value would be an unknown option or an argument.
TEST_F(Programs, GoodValuesEitherWay)
{
	struct GoodValue {
		const char *program;
		std::vector<std::string> before;
		const char *flag;
		const char *value;
		const char *message;
	};
	const std::vector<GoodValue> cases = {
		{ "calped-detect", { "missing-input.png" }, "--model", "m.cpm", "missing-input.png" },
		{ "calped-eval", { "--frames", "no-frames", "--model", "m" }, "--gt", "missing-gt.txt",
		  "missing-gt.txt" },
		{ "calped-convert", { "missing.mat", "out.cpm" }, "--name", "x", "missing.mat" },
		{ "calped-calibrate", { "missing.csv" }, "--unit", "mm", "missing.csv" },
		{ "calped-calibrate", { "missing.csv" }, "--output", "p.txt", "missing.csv" },
		{ "calped-play", { "--model", "m" }, "--input", "missing-frames", "missing-frames" },
	};
	for (const GoodValue &c : cases) {
		if (!has(c.program))
			continue;
		const auto args = bothWays(c.before, c.flag, c.value);
		const ProcessResult a = run(c.program, args.first), b = run(c.program, args.second);
		expectError(c.program, a, 1, c.message);
		expectError(c.program, b, 1, c.message);
		EXPECT_EQ(a.err, b.err) << c.program << " " << c.flag;
	}
}

TEST_F(Programs, CrossFlagUsageErrors)
{
	expectError("calped-detect", run("calped-detect", { "--model", "m", "--levels", "toolbox", "x.png" }), 2,
		    "--levels applies to the calibrated method only");
	expectError("calped-play", run("calped-play", { "--input", "x", "--model", "m", "--method", "calibrated" }),
		    2, "--method calibrated needs --calib FILE");
	expectError("calped-eval",
		    run("calped-eval", { "--frames", "f", "--gt", "g", "--model", "m", "--resizes", "0.5",
					 "--resize-at", "pyramid" }),
		    2, "--resize-at pyramid needs --resize >= 1");
	if (has("calped-convert")) {
		expectError("calped-convert", run("calped-convert", { "only-one.mat" }), 2,
			    "expected two arguments");
	}
	// An unambiguous prefix is the option; an ambiguous one is named with its candidates.
	expectError("calped-detect", run("calped-detect", { "--resize-a=frame", "--model", "m", "missing.png" }), 1,
		    "missing.png");
	expectError("calped-detect", run("calped-detect", { "--re=2", "--model", "m", "x.png" }), 2,
		    "ambiguous option '--re'");
}

} // namespace

int main(int argc, char **argv)
{
	::testing::InitGoogleTest(&argc, argv);
	for (int i = 1; i < argc; i++) {
		const std::string a = argv[i];
		const size_t eq = a.find('=', 10);
		if (a.rfind("--program=", 0) == 0 && eq != std::string::npos)
			gPrograms[a.substr(10, eq - 10)] = a.substr(eq + 1);
	}
	return RUN_ALL_TESTS();
}
