// SPDX-License-Identifier: BSD-2-Clause
#include "test_model.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#include "process.h"

namespace fs = std::filesystem;

namespace calped::test {

namespace {

std::string gModelDir;

} // namespace

const std::string &convertedModel(const std::string &convertPath, std::string &skipReason)
{
	static std::string model;
	static std::string reason;
	static bool tried = false;
	if (!tried) {
		tried = true;
		const char *shared = std::getenv("CALPED_SHARED_DIR");
		std::string mat = std::string(shared ? shared : "../shared") +
				  "/models/dollar-toolbox/AcfInriaDetector.mat";
		if (!fs::exists(mat)) {
			reason = "no " + mat + " (../shared models absent)";
		} else if (convertPath.empty() || !fs::exists(convertPath)) {
			reason = "calped-convert is not built (" + convertPath + ")";
		} else {
			std::string pattern = (fs::temp_directory_path() / "calped-cli-model-XXXXXX").string();
			std::vector<char> buf(pattern.begin(), pattern.end());
			buf.push_back('\0');
			if (!mkdtemp(buf.data()))
				throw std::runtime_error("mkdtemp failed");
			gModelDir = buf.data();
			std::string out = gModelDir + "/AcfInriaDetector.cpm";
			ProcessResult r = runProcess(convertPath, { mat, out }, gModelDir);
			if (!r.exited || r.exitCode != 0 || !fs::exists(out))
				reason = "FAIL: calped-convert " + mat + " failed: " + r.err;
			else
				model = out;
		}
	}
	skipReason = reason;
	return model;
}

void removeConvertedModel()
{
	if (gModelDir.empty())
		return;
	std::error_code ec;
	fs::remove_all(gModelDir, ec);
}

} // namespace calped::test
