// SPDX-License-Identifier: BSD-2-Clause
// Runs every (method, resize) in a child process of its own: the peak resident memory
// (getrusage ru_maxrss) is then the run's own, not the largest of all runs so far, and
// `jobs` runs can share the cores of a small machine.
#pragma once

#include <string>
#include <vector>

#include "methods.h"
#include "run.h"

namespace calped::eval_tool {

struct RunSpec {
	const MethodEntry *method = nullptr;
	double resize = 1.0;
};

// Results come back in the order of `specs`, without their evaluation. Fails on the first
// failed run (its message names the run), stopping the others.
bool runAll(const std::vector<RunSpec> &specs, const RunSettings &settings, int jobs,
	    std::vector<RunResult> &results, std::string &error);

// The bytes a child sends back, exposed for the tests.
std::vector<unsigned char> encodeRun(const RunResult &run);
bool decodeRun(const std::vector<unsigned char> &bytes, RunResult &run, std::string &error);

} // namespace calped::eval_tool
