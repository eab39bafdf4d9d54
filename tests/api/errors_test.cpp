// SPDX-License-Identifier: BSD-2-Clause
// Errors are API: every ErrorCode has its own name, and docs/errors.md documents each one
// (and nothing else) in its table.
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <calped/status.h>

namespace calped {
namespace {

// The last enumerator; ErrorIsLast below fails when a code is added after it.
constexpr ErrorCode kLastCode = ErrorCode::EndOfStream;

std::string errorsDoc()
{
	const char *source = std::getenv("CALPED_SOURCE_DIR");
	std::ifstream in(std::string(source ? source : ".") + "/docs/errors.md");
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

// Codes named in the first column of the table: "| `Name` | ...", with the row's line.
std::map<std::string, int> documentedCodes(const std::string &doc, std::multiset<std::string> &all)
{
	std::map<std::string, int> rows;
	std::istringstream lines(doc);
	std::string line;
	int n = 0;
	while (std::getline(lines, line)) {
		n++;
		if (line.rfind("| `", 0) != 0)
			continue;
		const size_t end = line.find('`', 3);
		if (end == std::string::npos)
			continue;
		const std::string name = line.substr(3, end - 3);
		all.insert(name);
		rows[name] = n;
	}
	return rows;
}

TEST(Errors, EveryCodeHasADistinctName)
{
	std::set<std::string> names;
	for (int c = 0; c <= static_cast<int>(kLastCode); c++) {
		const std::string name = errorCodeName(static_cast<ErrorCode>(c));
		EXPECT_NE(name, "Unknown") << "code " << c << " has no name";
		EXPECT_TRUE(names.insert(name).second) << "code " << c << " repeats the name " << name;
	}
	EXPECT_EQ(names.size(), static_cast<size_t>(kLastCode) + 1);
}

TEST(Errors, LastCodeIsTheLastOne)
{
	// A code added after kLastCode would escape the other tests: move kLastCode to it.
	EXPECT_STREQ(errorCodeName(static_cast<ErrorCode>(static_cast<int>(kLastCode) + 1)),
		     "Unknown");
}

TEST(Errors, MessagesStartWithTheCodeName)
{
	for (int c = 1; c <= static_cast<int>(kLastCode); c++) {
		const ErrorCode code = static_cast<ErrorCode>(c);
		const Status st = Status::error(code, "field %s = %d", "x", c);
		EXPECT_FALSE(st.ok());
		EXPECT_EQ(st.code(), code);
		EXPECT_EQ(std::string(st.message()),
			  std::string(errorCodeName(code)) + ": field x = " + std::to_string(c));
	}
	EXPECT_TRUE(Status::success().ok());
}

TEST(Errors, EveryCodeIsDocumentedOnceAndOnlyRealCodes)
{
	const std::string doc = errorsDoc();
	ASSERT_FALSE(doc.empty()) << "docs/errors.md not found (CALPED_SOURCE_DIR)";
	std::multiset<std::string> all;
	const std::map<std::string, int> rows = documentedCodes(doc, all);
	std::set<std::string> real;
	for (int c = 1; c <= static_cast<int>(kLastCode); c++) {
		const std::string name = errorCodeName(static_cast<ErrorCode>(c));
		real.insert(name);
		EXPECT_EQ(all.count(name), 1u) << name << " needs exactly one row in docs/errors.md";
	}
	for (const auto &row : rows)
		EXPECT_TRUE(real.count(row.first))
			<< "docs/errors.md line " << row.second << " documents `" << row.first
			<< "`, which is not an ErrorCode";
}

} // namespace
} // namespace calped
