// SPDX-License-Identifier: BSD-2-Clause
// Both ground-truth readers on small files, including malformed ones: every error must
// name the file and the line.
#include <algorithm>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "ground_truth.h"
#include "test_paths.h"

namespace calped::eval_tool {
namespace {

using test::dataPath;

// Loads a file that must fail and checks the message starts "PATH:LINE: " and mentions `what`.
void expectLineError(const std::string &name, long line, const std::string &what)
{
	const std::string path = dataPath(name);
	GroundTruth gt;
	std::string error;
	EXPECT_FALSE(loadGroundTruth(path, gt, error)) << name;
	EXPECT_EQ(error.rfind(path + ":" + std::to_string(line) + ": ", 0), 0u)
		<< "error for " << name << ": " << error;
	EXPECT_NE(error.find(what), std::string::npos) << "error for " << name << ": " << error;
	EXPECT_EQ(gt.lastFrame(), 0) << "a failed read leaves no boxes";
}

TEST(CvmlReader, ReadsBoxesAndNumbersFramesFromOne)
{
	if (!cvmlSupported())
		GTEST_SKIP() << "built without expat";
	GroundTruth gt;
	std::string error;
	ASSERT_TRUE(loadGroundTruth(dataPath("cvml_small.xml"), gt, error)) << error;
	EXPECT_EQ(gt.lastFrame(), 4); // CVML frame 3 is our frame 4
	ASSERT_EQ(gt.boxes(1).size(), 2u);
	EXPECT_TRUE(gt.boxes(2).empty());
	EXPECT_TRUE(gt.boxes(3).empty());
	ASSERT_EQ(gt.boxes(4).size(), 1u);
	// Centre and size -> corner and size.
	const Box &b = gt.boxes(1)[0].box;
	EXPECT_DOUBLE_EQ(b.x, 100);
	EXPECT_DOUBLE_EQ(b.y, 200);
	EXPECT_DOUBLE_EQ(b.w, 30);
	EXPECT_DOUBLE_EQ(b.h, 80);
	EXPECT_DOUBLE_EQ(gt.boxes(1)[1].box.w, 33.25);
	EXPECT_DOUBLE_EQ(gt.boxes(4)[0].box.x, 0);
	EXPECT_FALSE(gt.boxes(1)[0].ignore);
	EXPECT_EQ(gt.count(4, false), 3);
	EXPECT_EQ(gt.count(1, false), 2);
}

TEST(CvmlReader, MalformedFilesNameFileAndLine)
{
	if (!cvmlSupported())
		GTEST_SKIP() << "built without expat";
	expectLineError("cvml_syntax_error.xml", 7, "malformed XML");
	expectLineError("cvml_missing_width.xml", 9, "lacks attribute \"w\"");
	expectLineError("cvml_bad_number.xml", 6, "w=\"3O\" is not a number");
	expectLineError("cvml_duplicate_frame.xml", 6, "first at line 3");
	expectLineError("cvml_box_outside_object.xml", 4, "<box> outside an <object>");
	expectLineError("cvml_negative_frame.xml", 3, "not a whole number");
}

TEST(CvmlReader, WithoutExpatSaysWhy)
{
	if (cvmlSupported())
		GTEST_SKIP() << "built with expat";
	GroundTruth gt;
	std::string error;
	EXPECT_FALSE(loadGroundTruth(dataPath("cvml_small.xml"), gt, error));
	EXPECT_NE(error.find("without expat"), std::string::npos) << error;
}

TEST(CvmlReader, PetsGroundTruth)
{
	const std::string path = test::envOr("CALPED_SHARED_DIR", "../shared") +
				 "/data/pets2009-s2l1/PETS2009-S2L1.xml";
	if (!cvmlSupported() || !std::ifstream(path))
		GTEST_SKIP() << "needs expat and " << path;
	GroundTruth gt;
	std::string error;
	ASSERT_TRUE(loadGroundTruth(path, gt, error)) << error;
	EXPECT_EQ(gt.lastFrame(), 795);
	EXPECT_EQ(gt.count(795, false), 4650);
	EXPECT_EQ(gt.boxes(1).size(), 3u); // annotation frame 0
}

TEST(MotReader, ReadsBoxesAndIgnoreFlags)
{
	GroundTruth gt;
	std::string error;
	ASSERT_TRUE(loadGroundTruth(dataPath("mot_small.txt"), gt, error)) << error;
	EXPECT_EQ(gt.lastFrame(), 4);
	ASSERT_EQ(gt.boxes(1).size(), 2u);
	EXPECT_FALSE(gt.boxes(1)[0].ignore);
	EXPECT_TRUE(gt.boxes(1)[1].ignore); // column 7 == 0
	EXPECT_EQ(gt.boxes(2).size(), 1u);
	EXPECT_TRUE(gt.boxes(3).empty());
	const Box &b = gt.boxes(4)[0].box; // already corner and size, frames already 1-based
	EXPECT_DOUBLE_EQ(b.x, 10.5);
	EXPECT_DOUBLE_EQ(b.y, 20.25);
	EXPECT_DOUBLE_EQ(b.w, 40);
	EXPECT_DOUBLE_EQ(b.h, 100);
	EXPECT_EQ(gt.count(4, false), 3);
	EXPECT_EQ(gt.count(4, true), 1);
}

TEST(MotReader, MalformedFilesNameFileAndLine)
{
	expectLineError("mot_few_fields.txt", 3, "got 3");
	expectLineError("mot_bad_number.txt", 2, "y \"2O1\" is not a number");
	expectLineError("mot_frame_zero.txt", 1, "1-based");
	expectLineError("mot_negative_size.txt", 2, "not positive");
}

// Found by fuzzing (tests/fuzz/regressions/gt_*): a field quoted in a message must not carry
// control characters from the file into the one-line error.
bool printable(const std::string &s)
{
	for (char c : s)
		if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
			return false;
	return true;
}

TEST(MotReader, MessagesStayOnePrintableLine)
{
	const std::string text = "1,1,10,20,30,40\n2,1,\x1b[2J\r\x07,20,30,40\n";
	GroundTruth gt;
	std::string error;
	EXPECT_FALSE(parseMotGroundTruth(text.data(), text.size(), "gt.txt", gt, error));
	EXPECT_EQ(error.rfind("gt.txt:2: x \"", 0), 0u) << error;
	EXPECT_TRUE(printable(error)) << error;
	EXPECT_EQ(gt.lastFrame(), 0);
}

TEST(CvmlReader, MessagesStayOnePrintableLine)
{
	if (!cvmlSupported())
		GTEST_SKIP() << "built without expat";
	const std::string text = "<dataset>\n<frame number=\"0\"><objectlist><object id=\"1\">\n"
				 "<box h=\"&#127;[2J&#10;\" w=\"3\" xc=\"1\" yc=\"1\"/>"
				 "</object></objectlist></frame></dataset>\n";
	GroundTruth gt;
	std::string error;
	EXPECT_FALSE(parseCvmlGroundTruth(text.data(), text.size(), "gt.xml", gt, error));
	EXPECT_EQ(error.rfind("gt.xml:3: <box> attribute h=", 0), 0u) << error;
	EXPECT_TRUE(printable(error)) << error;
}

// Frame numbers are stored sparsely: a file naming frame 10^15 (a quarter of the largest
// long where long has 32 bits) costs one box, not a table of that many frames (which used
// to throw bad_alloc, or loop for ever counting boxes).
TEST(MotReader, HugeFrameNumberCostsOneBox)
{
	const long huge = long(std::min<long long>(1000000000000000LL, std::numeric_limits<long>::max() / 4));
	const std::string text = std::to_string(huge) + ",1,10,20,30,40\n3,2,1,2,3,4,0\n";
	GroundTruth gt;
	std::string error;
	ASSERT_TRUE(parseMotGroundTruth(text.data(), text.size(), "gt.txt", gt, error)) << error;
	EXPECT_EQ(gt.lastFrame(), huge);
	EXPECT_EQ(gt.count(gt.lastFrame(), false), 1);
	EXPECT_EQ(gt.count(gt.lastFrame(), true), 1);
	EXPECT_EQ(gt.count(2, true), 0);
	EXPECT_EQ(gt.boxes(huge).size(), 1u);
	EXPECT_TRUE(gt.boxes(999).empty());
}

TEST(GroundTruth, MissingFileIsNamed)
{
	GroundTruth gt;
	std::string error;
	EXPECT_FALSE(loadGroundTruth(dataPath("no-such-file.xml"), gt, error));
	EXPECT_NE(error.find("no-such-file.xml"), std::string::npos) << error;
}

} // namespace
} // namespace calped::eval_tool
