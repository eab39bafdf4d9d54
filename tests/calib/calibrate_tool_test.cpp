// SPDX-License-Identifier: BSD-2-Clause
// calped-calibrate: its CSV reader, then the tool end to end (path in CALPED_CALIBRATE).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "calib_test_util.h"
#include "correspondences.h"

namespace calped {
namespace {

using namespace calib_test;
using calibrate_tool::Correspondences;
using calibrate_tool::parseCorrespondences;

// CSV of the pitched camera: two heights over a ground grid, world in `scale` units/metre.
std::string pitchedCsv(double scale)
{
	const CameraModel cam = pitchedCamera();
	std::string csv = "u,v,X,Y,Z\n# synthetic\n";
	for (double y = 10; y <= 30; y += 10)
		for (double x = -6; x <= 6; x += 6)
			for (double z : { 0.0, 1.8 }) {
				const Eigen::Vector2d p = cam.project(Eigen::Vector3d(x, y, z));
				char line[160];
				std::snprintf(line, sizeof(line), "%.12f,%.12f,%g,%g,%g\n", p.x(), p.y(),
					      x * scale, y * scale, z * scale);
				csv += line;
			}
	return csv;
}

Status parse(const std::string &text, Correspondences &c)
{
	return parseCorrespondences(text.data(), text.size(), "pts.csv", c);
}

TEST(CorrespondenceCsv, Reads)
{
	Correspondences c;
	Status st = parse(" U , V , x , y , z \r\n\n1,2,3,4,5\r\n# comment\n6, 7, 8e0, -9, +10\n", c);
	ASSERT_TRUE(st.ok()) << st.message();
	ASSERT_EQ(c.points.size(), 2u);
	EXPECT_EQ(c.points[1].image, Eigen::Vector2d(6, 7));
	EXPECT_EQ(c.points[1].world, Eigen::Vector3d(8, -9, 10));
	EXPECT_EQ(c.lines[0], 3);
	EXPECT_EQ(c.lines[1], 5);
}

TEST(CorrespondenceCsv, Errors)
{
	const struct {
		std::string text;
		const char *message;
	} cases[] = {
		{ "", "ParseError: pts.csv: empty (expected the header 'u,v,X,Y,Z' and points)" },
		{ "1,2,3,4,5\n", "ParseError: pts.csv:1: expected the header 'u,v,X,Y,Z', found '1,2,3,4,5'" },
		{ "u,v,X,Y,Z\n1,2,3,4\n", "ParseError: pts.csv:2: expected 5 fields (u,v,X,Y,Z), found 4" },
		{ "u,v,X,Y,Z\n1,2,3,4,5,6\n", "ParseError: pts.csv:2: expected 5 fields (u,v,X,Y,Z), found more than 5" },
		{ "u,v,X,Y,Z\n1,2,3,4,5\n1,2,three,4,5\n", "ParseError: pts.csv:3: X 'three' is not a number" },
		{ "u,v,X,Y,Z\n1,nan,3,4,5\n", "ParseError: pts.csv:2: v 'nan' is not a finite number" },
		{ "u,v,X,Y,Z\n1,2,3,4,\n", "ParseError: pts.csv:2: Z '' is not a number" },
		{ "u,v,X,Y,Z\n0x10,2,3,4,5\n", "ParseError: pts.csv:2: u '0x10' is not a number" },
	};
	for (const auto &c : cases) {
		Correspondences out;
		EXPECT_STREQ(parse(c.text, out).message(), c.message);
	}
}

// Runs calped-calibrate with `args`; returns its exit status and combined output.
int runTool(const std::string &args, std::string &output)
{
	const char *exe = std::getenv("CALPED_CALIBRATE");
	const std::string cmd = std::string("'") + exe + "' " + args + " 2>&1";
	FILE *p = popen(cmd.c_str(), "r");
	if (!p)
		return -1;
	output.clear();
	char buf[512];
	size_t n;
	while ((n = fread(buf, 1, sizeof(buf), p)) > 0)
		output.append(buf, n);
	const int status = pclose(p);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CalibrateTool : public ::testing::Test
{
protected:
	void SetUp() override
	{
		if (!std::getenv("CALPED_CALIBRATE"))
			GTEST_SKIP() << "CALPED_CALIBRATE not set (run through meson test)";
		dir_ = ::testing::TempDir();
	}
	std::string write(const std::string &name, const std::string &text)
	{
		const std::string path = dir_ + "calib_tool_" + name;
		FILE *f = std::fopen(path.c_str(), "wb");
		EXPECT_TRUE(f);
		if (f) {
			std::fwrite(text.data(), 1, text.size(), f);
			std::fclose(f);
		}
		return path;
	}
	std::string dir_;
};

TEST_F(CalibrateTool, RecoversTheCameraAndWritesP)
{
	const std::string csv = write("mm.csv", pitchedCsv(1000.0));
	const std::string out = dir_ + "calib_tool_P.txt";
	std::string log;
	ASSERT_EQ(runTool("--unit mm -o '" + out + "' '" + csv + "'", log), 0) << log;
	EXPECT_NE(log.find("18 correspondences, world unit mm"), std::string::npos) << log;
	EXPECT_NE(log.find("reprojection error RMS"), std::string::npos) << log;
	EXPECT_NE(log.find("camera centre (x, y, z) = (0.0000, 0.0000, 10.0000) m"),
		  std::string::npos)
		<< log;
	std::string text;
	ASSERT_TRUE(readFile(out, text));
	EXPECT_NE(text.find("\nunit: mm\n"), std::string::npos) << text;
	EXPECT_NE(text.find("# reprojection error RMS"), std::string::npos) << text;
	CameraModel m;
	Status st = loadCalibration(text.data(), text.size(), "P.txt", m);
	ASSERT_TRUE(st.ok()) << st.message();
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_F(CalibrateTool, ExampleFileOfTheDocs)
{
	// docs/calibration.md runs the tool on this file.
	std::string log;
	ASSERT_EQ(runTool("'" + dataPath("pitched_points.csv") + "'", log), 0) << log;
	EXPECT_NE(log.find("10 correspondences, world unit m"), std::string::npos) << log;
	EXPECT_NE(log.find("camera centre (x, y, z) = (0.0000, 0.0000, 10.0000) m"),
		  std::string::npos)
		<< log;
}

TEST_F(CalibrateTool, WritesToStandardOutput)
{
	const std::string csv = write("m.csv", pitchedCsv(1.0));
	std::string log;
	ASSERT_EQ(runTool("--quiet '" + csv + "'", log), 0) << log;
	EXPECT_EQ(log.find("calped-calibrate: 18 correspondences"), std::string::npos) << log;
	CameraModel m;
	Status st = loadProjectionText(log.data(), log.size(), "stdout", m);
	ASSERT_TRUE(st.ok()) << st.message() << "\n" << log;
	EXPECT_LT((m.projection() - pitchedCamera().projection()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_F(CalibrateTool, Errors)
{
	std::string log;
	const std::string good = pitchedCsv(1.0);
	// Fewer than 6 points.
	const std::string five =
		write("five.csv", "u,v,X,Y,Z\n1,2,3,4,5\n2,3,4,5,6\n3,4,5,6,8\n4,5,6,7,9\n5,6,7,8,1\n");
	EXPECT_EQ(runTool("'" + five + "'", log), 1);
	EXPECT_NE(log.find("at least 6 correspondences, got 5"), std::string::npos) << log;
	// Coplanar.
	std::string flat = "u,v,X,Y,Z\n";
	const CameraModel cam = pitchedCamera();
	for (double y = 10; y <= 30; y += 10)
		for (double x = -6; x <= 6; x += 6) {
			const Eigen::Vector2d p = cam.project(Eigen::Vector3d(x, y, 0));
			flat += std::to_string(p.x()) + "," + std::to_string(p.y()) + "," +
				std::to_string(x) + "," + std::to_string(y) + ",0\n";
		}
	EXPECT_EQ(runTool("'" + write("flat.csv", flat) + "'", log), 1);
	EXPECT_NE(log.find("coplanar"), std::string::npos) << log;
	// Unreadable CSV: the file and line are named.
	const std::string bad = write("bad.csv", edit(good, "\n# synthetic\n", "\n# synthetic\n1;2;3;4;5\n"));
	EXPECT_EQ(runTool("'" + bad + "'", log), 1);
	EXPECT_NE(log.find("bad.csv:3: expected 5 fields"), std::string::npos) << log;
	// Missing file, bad options.
	EXPECT_EQ(runTool("'" + dir_ + "calib_tool_missing.csv'", log), 1);
	EXPECT_NE(log.find("cannot read"), std::string::npos) << log;
	EXPECT_EQ(runTool("--unit ft x.csv", log), 2);
	EXPECT_NE(log.find("--unit: expected mm, cm or m, got 'ft'"), std::string::npos) << log;
	EXPECT_EQ(runTool("", log), 2);
	EXPECT_EQ(runTool("--frobnicate x.csv", log), 2);
	EXPECT_EQ(runTool("--help", log), 0);
	EXPECT_NE(log.find("usage: calped-calibrate"), std::string::npos);
}

} // namespace
} // namespace calped
