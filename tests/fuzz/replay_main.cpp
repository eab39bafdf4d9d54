// SPDX-License-Identifier: BSD-2-Clause
// Runs a fuzz target's LLVMFuzzerTestOneInput on files, without libFuzzer: the normal test
// suite replays every seed and every input fuzzing ever found (tests/fuzz/corpus/<target>,
// tests/fuzz/regressions/<target>), so the parsers stay fixed in every build, including the
// sanitizer one. Usage: replay_<target> FILE_OR_DIR...; exits 1 on an unreadable argument or
// an empty set; a crash or sanitizer report is the target's own.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace {

bool readFile(const std::string &path, std::vector<uint8_t> &out)
{
	FILE *f = std::fopen(path.c_str(), "rb");
	if (!f)
		return false;
	out.clear();
	uint8_t buffer[65536];
	size_t n;
	while ((n = std::fread(buffer, 1, sizeof(buffer), f)) > 0)
		out.insert(out.end(), buffer, buffer + n);
	const bool ok = !std::ferror(f);
	std::fclose(f);
	return ok;
}

// Files of a folder (not recursive, no dot files), or the path itself.
bool collect(const std::string &path, std::vector<std::string> &files)
{
	struct stat st;
	if (stat(path.c_str(), &st) != 0)
		return false;
	if (!S_ISDIR(st.st_mode)) {
		files.push_back(path);
		return true;
	}
	DIR *d = opendir(path.c_str());
	if (!d)
		return false;
	while (dirent *e = readdir(d))
		if (e->d_name[0] != '.')
			files.push_back(path + "/" + e->d_name);
	closedir(d);
	return true;
}

} // namespace

int main(int argc, char **argv)
{
	std::vector<std::string> files;
	for (int i = 1; i < argc; i++) {
		if (!collect(argv[i], files)) {
			std::fprintf(stderr, "replay: cannot read %s\n", argv[i]);
			return 1;
		}
	}
	if (files.empty()) {
		std::fprintf(stderr, "replay: no inputs (usage: replay FILE_OR_DIR...)\n");
		return 1;
	}
	std::vector<uint8_t> bytes;
	for (const std::string &f : files) {
		if (!readFile(f, bytes)) {
			std::fprintf(stderr, "replay: cannot read %s\n", f.c_str());
			return 1;
		}
		std::printf("%s (%zu bytes)\n", f.c_str(), bytes.size());
		std::fflush(stdout); // the last name printed is the input that crashed
		// A copy of exactly the input's size, so an overread is caught as under libFuzzer.
		std::vector<uint8_t> exact(bytes);
		LLVMFuzzerTestOneInput(exact.empty() ? nullptr : exact.data(), exact.size());
	}
	std::printf("replayed %zu inputs\n", files.size());
	return 0;
}
