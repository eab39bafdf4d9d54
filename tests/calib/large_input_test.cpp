// SPDX-License-Identifier: BSD-2-Clause
// The calibration parsers are linear in their input: MB-sized crafted files that took tens
// of seconds (a Tsai XML tag of 100k attributes: 34 s; an OpenCV YAML line of 1M values:
// 66 s) are answered in well under the bound below, which is generous (a slow machine,
// the sanitizers) but far below what a quadratic scan takes on them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <calped/calibration.h>

namespace calped {
namespace {

// Linear: about 1.5 s here, 5x that under the sanitizers or qemu (the cross suite); the
// quadratic scans took 34 s (100k attributes; 76 s for these 150k) and 66 s.
constexpr double kBoundSeconds = 45;

template <typename Load>
Status timedLoad(Load load, const std::string &text, const char *name, double &seconds)
{
	CameraModel camera;
	const auto start = std::chrono::steady_clock::now();
	const Status st = load(text.data(), text.size(), name, camera);
	seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return st;
}

TEST(LargeInputs, TsaiXmlWithManyAttributesInOneTag)
{
	std::string attributes;
	for (int i = 0; i < 150000; i++)
		attributes += " a" + std::to_string(i) + "=\"1\"";
	ASSERT_GT(attributes.size(), 1500000u);
	double seconds = 0;
	// All distinct: the reader takes them and the loader refuses the first it does not know.
	Status st = timedLoad(loadTsaiXml, "<?xml version=\"1.0\"?>\n<Camera name=\"c\"" + attributes + ">\n</Camera>\n",
			      "many.xml", seconds);
	EXPECT_EQ(st.code(), ErrorCode::ParseError) << st.message();
	EXPECT_LT(seconds, kBoundSeconds);
	std::printf("[ time     ] %.3f s\n", seconds);
	// The same with the first one repeated at the end: found as a duplicate.
	st = timedLoad(loadTsaiXml,
		       "<?xml version=\"1.0\"?>\n<Camera name=\"c\"" + attributes + " a0=\"2\">\n</Camera>\n",
		       "duplicate.xml", seconds);
	EXPECT_EQ(st.code(), ErrorCode::ParseError);
	EXPECT_NE(std::string(st.message()).find("duplicate attribute 'a0'"), std::string::npos) << st.message();
	EXPECT_LT(seconds, kBoundSeconds);
	std::printf("[ time     ] %.3f s\n", seconds);
}

TEST(LargeInputs, OpenCvYamlWithManyValuesOnOneLine)
{
	std::string values = "1";
	for (int i = 1; i < 1000000; i++)
		values += ",1";
	ASSERT_GT(values.size(), 1900000u);
	double seconds = 0;
	const Status st = timedLoad(loadOpenCvYaml,
				    "%YAML:1.0\ncamera_matrix: !!opencv-matrix { rows: 3, cols: 3, dt: d, data: [ " +
					    values + " ] }\n",
				    "values.yml", seconds);
	EXPECT_EQ(st.code(), ErrorCode::ParseError) << st.message();
	EXPECT_NE(std::string(st.message()).find("values.yml"), std::string::npos) << st.message();
	EXPECT_LT(seconds, kBoundSeconds);
	std::printf("[ time     ] %.3f s\n", seconds);
}

} // namespace
} // namespace calped
