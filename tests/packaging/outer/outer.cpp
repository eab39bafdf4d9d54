// SPDX-License-Identifier: BSD-2-Clause
// The outer project's program (tests/packaging/outer/meson.build): configured, not built.
#include <calped/calped.h>

#include <cstdio>

int main()
{
	std::printf("calped %s\n", CALPED_VERSION);
	return 0;
}
