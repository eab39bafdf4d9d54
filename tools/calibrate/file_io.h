// SPDX-License-Identifier: BSD-2-Clause
// Whole-file reads and writes whose errors come back as one-line messages.
#pragma once

#include <string>

namespace calped::calibrate_tool {

bool readTextFile(const std::string &path, std::string &out, std::string &error);
bool writeTextFile(const std::string &path, const std::string &text, std::string &error);

} // namespace calped::calibrate_tool
