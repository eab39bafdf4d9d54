// SPDX-License-Identifier: BSD-2-Clause
// Where the eval tests find their inputs (set by tests/eval/meson.build).
#pragma once

#include <cstdlib>
#include <string>

namespace calped::eval_tool::test {

inline std::string envOr(const char *name, const char *fallback)
{
	const char *v = std::getenv(name);
	return v && *v ? v : fallback;
}

// tests/eval/data/NAME
inline std::string dataPath(const std::string &name)
{
	return envOr("CALPED_EVAL_TEST_DATA", "tests/eval/data") + "/" + name;
}

} // namespace calped::eval_tool::test
