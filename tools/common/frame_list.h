// SPDX-License-Identifier: BSD-2-Clause
// Turns the command line's INPUTs into the ordered list of image files.
#pragma once

#include <string>
#include <vector>

namespace calped::apps {

// Expands each input in order with the file port's listing (ports/file/image_folder.h):
// a file stays as it is, a folder contributes its image files sorted by name (not
// recursive). Fails on a missing input or a folder with no images, so a typo never becomes
// an empty run.
bool listFrames(const std::vector<std::string> &inputs, std::vector<std::string> &frames,
		std::string &error);

} // namespace calped::apps
