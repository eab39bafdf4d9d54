// SPDX-License-Identifier: BSD-2-Clause
// Small file helpers whose errors come back as one-line messages, never exceptions.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image_io.h"

namespace calped::apps {

using ports::kMaxCalibrationFileBytes;
using ports::kMaxModelFileBytes;
using ports::kMaxTableFileBytes;

// Reads a whole regular file into memory, at most maxBytes (ports::kMax*FileBytes, by the
// file's kind; docs/errors.md). `what` names the file's role in the error ("model ").
bool readFile(const std::string &path, std::vector<uint8_t> &out, std::string &error,
	      const std::string &what, size_t maxBytes);

// The same as text (a table: CSV, ground truth; ports::kMaxTableFileBytes unless told),
// and writing a whole text file ("-" is not special).
bool readTextFile(const std::string &path, std::string &out, std::string &error,
		  size_t maxBytes = kMaxTableFileBytes);
bool writeTextFile(const std::string &path, const std::string &text, std::string &error);

// True for an existing regular file (symlinks followed).
bool isRegularFile(const std::string &path);

// Creates a folder and its parents if missing.
bool makeDirectories(const std::string &path, std::string &error);

} // namespace calped::apps
