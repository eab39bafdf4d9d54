// SPDX-License-Identifier: BSD-2-Clause
// An output file written beside its final name and renamed into place by commit(): a run
// that fails or stops half-way never leaves a half-written file, nor deletes what was there
// (an earlier result, or something that is not a file at all: a device node is refused,
// never replaced).
#pragma once

#include <cstdio>
#include <string>

namespace calped {
namespace ports {

class AtomicFile
{
public:
	AtomicFile() = default;
	~AtomicFile(); // without commit(): the temporary file is removed, `path` untouched
	AtomicFile(const AtomicFile &) = delete;
	AtomicFile &operator=(const AtomicFile &) = delete;

	// Creates PATH.tmp-PID-N in PATH's folder. Refuses a PATH that exists and is not a
	// regular file (a folder, a device, a FIFO).
	bool open(const std::string &path, std::string &error);
	FILE *get() { return file_; }
	bool isOpen() const { return file_ != nullptr; }
	// Flushes, closes and renames over `path`; false (and the temporary removed) if any
	// write failed (a full disk).
	bool commit(std::string &error);
	// Removes the temporary file; `path` untouched.
	void discard();

private:
	FILE *file_ = nullptr;
	std::string path_, temp_;
};

} // namespace ports
} // namespace calped
