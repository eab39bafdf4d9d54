// SPDX-License-Identifier: BSD-2-Clause
// Input quoted in messages (lib/src/text/excerpt.h), and the messages of the calibration
// loaders and calped-calibrate's CSV on hostile fields: one short printable UTF-8 line.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include <calped/calibration.h>

#include "correspondences.h"
#include "text/excerpt.h"

namespace calped {
namespace {

// One line of printable, well-formed UTF-8, at most `most` bytes.
void expectCleanLine(const std::string &m, size_t most)
{
	EXPECT_LE(m.size(), most) << m.substr(0, 200);
	const auto *s = reinterpret_cast<const unsigned char *>(m.data());
	for (size_t i = 0; i < m.size();) {
		ASSERT_FALSE(s[i] < 0x20 || s[i] == 0x7f) << "control byte at " << i << ": " << m;
		const size_t n = utf8CharLength(s + i, m.size() - i);
		ASSERT_NE(n, 0u) << "not UTF-8 at " << i << ": " << m;
		i += n;
	}
}

// A 1 MiB field of control characters, invalid UTF-8 and text.
std::string hostileField()
{
	std::string f;
	while (f.size() < (1u << 20))
		f += "ab\x01\x1b[31m\xff\xc3\x28\r\x7f\xed\xa0\x80\xf4\x90\x80\x80z";
	return f;
}

TEST(Excerpt, ControlBytesAndInvalidUtf8BecomeQuestionMarks)
{
	EXPECT_EQ(excerpt(std::string_view("a\tb\nc\x7f", 6)), "a?b?c?");
	EXPECT_EQ(excerpt("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
	// A lone continuation byte, a cut sequence, an overlong '/', a surrogate, above U+10FFFF.
	EXPECT_EQ(excerpt("\x80|\xc3|\xc0\xaf|\xed\xa0\x80|\xf4\x90\x80\x80"), "?|?|??|???|????");
	EXPECT_EQ(excerpt(std::string_view("a\0b", 3)), "a?b");
}

TEST(Excerpt, LongInputIsCutAtACharacterBoundary)
{
	const std::string sixty(60, 'x');
	EXPECT_EQ(excerpt(sixty), sixty);
	EXPECT_EQ(excerpt(sixty + "y"), sixty + "...");
	// A two-byte character straddling byte 60 is left out whole.
	EXPECT_EQ(excerpt(std::string(59, 'x') + "\xc3\xa9"), std::string(59, 'x') + "...");
	char small[8];
	EXPECT_STREQ(excerpt("abcdefghij", small, sizeof(small)), "abcd...");
	char one[1];
	EXPECT_STREQ(excerpt("abc", one, sizeof(one)), "");
	EXPECT_EQ(excerpt(std::string(100, 'x'), 10), std::string(10, 'x') + "...");
}

TEST(Excerpt, CalibrationLoaderMessagesAreShortCleanLines)
{
	const std::string field = hostileField();
	const std::string inputs[] = {
		"FocalLengthX = " + field + "\n",                       // Town Centre .ci
		"1 0 0 0\n0 1 0 0\n0 0 1 " + field + "\n",               // plain P
		"%YAML:1.0\n" + field + ": 1\n",                        // OpenCV YAML
		"<Camera name=\"" + field + "\"><Geometry width=\"" + field + "\"/></Camera>", // Tsai
	};
	const std::string name = "cam\x1b]0;title\x07\xff.txt";
	for (const std::string &text : inputs) {
		CameraModel cam;
		const Status st = loadCalibration(text.data(), text.size(), name.c_str(), cam);
		ASSERT_FALSE(st.ok());
		expectCleanLine(st.message(), 400);
		EXPECT_NE(std::strstr(st.message(), "cam?]0;title??.txt"), nullptr) << st.message();
	}
}

TEST(Excerpt, CalibrateCsvMessagesAreShortCleanLines)
{
	const std::string field = hostileField();
	for (const std::string &text : { field + "\n", "u,v,X,Y,Z\n1,2," + field + ",4,5\n" }) {
		calibrate_tool::Correspondences c;
		const Status st = calibrate_tool::parseCorrespondences(text.data(), text.size(),
								       "pts\x01\xfe.csv", c);
		ASSERT_FALSE(st.ok());
		expectCleanLine(st.message(), 300);
		EXPECT_NE(std::strstr(st.message(), "pts??.csv:"), nullptr) << st.message();
		EXPECT_NE(std::strstr(st.message(), "ab?"), nullptr) << st.message();
	}
}

} // namespace
} // namespace calped
