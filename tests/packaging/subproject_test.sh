#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# calped as a Meson subproject (meson test 'packaging-subproject', suite 'packaging'):
# configures the outer project in outer/ with calped's source tree as subprojects/calped
# and checks, from `meson introspect --targets` and the configure log, that
#   1. by default only the library is built (libcalped and its SIMD kernel libraries),
#      the outer program uses it, and neither GoogleTest nor the tools' libraries
#      (matio, stb, expat) nor the capture ports' (aravis, libcamera) are looked up;
#   2. -Dcalped:library_only=disabled brings the tools and tests back.
#   subproject_test.sh MESON SOURCEDIR CALPED_SOURCE_ROOT
# Only configures (no compiler runs beyond Meson's checks): a few seconds.
set -euo pipefail

meson=$1 srcdir=$2 calped_root=$3
say() { echo "packaging-subproject: $*"; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/calped-subproject.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cp -r "$srcdir/outer" "$tmp/outer"
mkdir "$tmp/outer/subprojects"
# A copy of the tracked tree would do as well; a link is quicker and Meson follows it.
ln -s "$calped_root" "$tmp/outer/subprojects/calped"

# The names of the targets the given build folder would build, "SUBPROJECT NAME" per line.
targets() {
	"$meson" introspect --targets "$1" | python3 -c '
import json, sys
for t in json.load(sys.stdin):
    print(t["subproject"] or "-", t["name"])'
}

say "meson setup (default options)"
"$meson" setup "$tmp/build" "$tmp/outer" >"$tmp/setup.log" 2>&1 || {
	cat "$tmp/setup.log"
	say "configuring the outer project failed"
	exit 1
}
list=$(targets "$tmp/build")
echo "$list" | sed 's/^/    /'
bad=$(grep -Ev '^calped (calped|calped_avx2|calped_neon)$|^- outer$' <<<"$list" || true)
[[ -z $bad ]] || { say "targets other than the library and the outer program:"; echo "$bad"; exit 1; }
grep -qx 'calped calped' <<<"$list" || { say "no libcalped target"; exit 1; }
grep -qx -- '- outer' <<<"$list" || { say "no outer program"; exit 1; }
looked_up=$(grep -Ei 'dependency.*(gtest|matio|stb|expat|aravis|libcamera)' "$tmp/build/meson-logs/meson-log.txt" || true)
[[ -z $looked_up ]] || { say "the library-only configure looked up:"; echo "$looked_up"; exit 1; }
say "library only; no GoogleTest, tool or port dependency looked up"

say "meson setup -Dcalped:library_only=disabled (ports off)"
"$meson" setup "$tmp/build-all" "$tmp/outer" -Dcalped:library_only=disabled \
	-Dcalped:aravis=disabled -Dcalped:libcamera=disabled >"$tmp/setup-all.log" 2>&1 || {
	cat "$tmp/setup-all.log"
	say "configuring with -Dcalped:library_only=disabled failed"
	exit 1
}
all=$(targets "$tmp/build-all")
say "$(grep -c '^calped ' <<<"$all") calped targets, among them:"
grep -E '^calped (calped-calibrate|kernel_tests)$' <<<"$all" | sed 's/^/    /'
grep -qx 'calped kernel_tests' <<<"$all" || { say "no tests with library_only=disabled"; exit 1; }
grep -qx 'calped calped-calibrate' <<<"$all" || { say "no tools with library_only=disabled"; exit 1; }
say "ok"
