// SPDX-License-Identifier: BSD-2-Clause
// A program outside calped, built by tests/packaging/pkgconfig_test.sh from the installed
// headers and library with nothing but `pkg-config --cflags --libs calped`. It prints the
// version it was compiled against and checks that a missing model is reported as an error.
#include <calped/calped.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

int main(int argc, char **argv)
{
	if (argc != 2) {
		std::fprintf(stderr, "usage: %s MODEL_FILE\n", argv[0]);
		return 2;
	}
	std::printf("calped %s\n", CALPED_VERSION);

	// The core reads models from memory (docs/model-format.md); an application reads the
	// file. A file that is not there gives no bytes, which the library must refuse.
	std::vector<uint8_t> bytes;
	std::ifstream in(argv[1], std::ios::binary);
	if (in)
		bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
	else
		std::printf("cannot open %s\n", argv[1]);

	calped::Model model;
	const calped::Status st = calped::loadModel(bytes.data(), bytes.size(), model);
	if (st.ok()) {
		std::printf("error: loadModel accepted %zu bytes of %s\n", bytes.size(), argv[1]);
		return 1;
	}
	if (std::strlen(st.message()) == 0 || model.nTrees != 0) {
		std::printf("error: the failure has no message or left a model behind\n");
		return 1;
	}
	// The message starts with the code's name (status.h), e.g. "ModelTruncated: ...".
	std::printf("model refused (%s): %s\n", calped::errorCodeName(st.code()), st.message());
	return 0;
}
