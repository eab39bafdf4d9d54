// SPDX-License-Identifier: BSD-2-Clause
#include "frame_list.h"

#include "cli_error.h"
#include "image_folder.h"

namespace calped::apps {

bool listFrames(const std::vector<std::string> &inputs, std::vector<std::string> &frames,
		std::string &error)
{
	frames.clear();
	std::vector<std::string> files;
	for (const std::string &input : inputs) {
		const Status st = ports::listImageFiles(input, files);
		if (!st.ok()) {
			error = statusText(st);
			return false;
		}
		frames.insert(frames.end(), files.begin(), files.end());
	}
	if (frames.empty()) {
		error = "no input frames";
		return false;
	}
	return true;
}

} // namespace calped::apps
