// SPDX-License-Identifier: BSD-2-Clause
// Small file helpers whose errors come back as one-line messages, never exceptions.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace calped::detect_tool {

// Reads a whole file into memory. `what` names the file's role in the error ("model ").
bool readFile(const std::string &path, std::vector<uint8_t> &out, std::string &error,
	      const std::string &what = "");

// Creates a folder and its parents if missing.
bool makeDirectories(const std::string &path, std::string &error);

} // namespace calped::detect_tool
