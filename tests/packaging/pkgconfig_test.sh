#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# calped as an installed package (meson test 'packaging-pkgconfig', suite 'packaging'):
# installs the build tree's library, headers and calped.pc into a temporary root
# (meson install --destdir, the 'devel' and, for a shared library, 'runtime' tags), builds
# consumer.cpp with nothing but `pkg-config --cflags --libs calped` against that root
# (PKG_CONFIG_PATH and PKG_CONFIG_SYSROOT_DIR), runs it and checks what it prints.
#   pkgconfig_test.sh MESON BUILDDIR SOURCEDIR VERSION DEFAULT_LIBRARY SANITIZE CROSS CXX...
# Exit 77 (skipped): a sanitizer build (its library needs the sanitizer runtime at link
# time, which no pkg-config consumer gets) and a cross build (the consumer would be
# a target program; the .pc file is the same as the native build's).
set -euo pipefail

meson=$1 builddir=$2 srcdir=$3 version=$4 default_library=$5 sanitize=$6 cross=$7
shift 7
cxx=("$@")
say() { echo "packaging-pkgconfig: $*"; }

if [[ $sanitize != none ]]; then
	say "skipped: -Db_sanitize=$sanitize; libcalped then needs -fsanitize=$sanitize when linked," \
		"which calped.pc does not carry (checked in the release build)"
	exit 77
fi
if [[ $cross == true ]]; then
	say "skipped: cross build; the consumer would be a target program (checked in the native build)"
	exit 77
fi
command -v pkg-config >/dev/null || { say "pkg-config not found (scripts/install-deps.sh installs it)"; exit 1; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/calped-pkgconfig.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
root=$tmp/root

tags=devel
[[ $default_library != static ]] && tags=devel,runtime
say "meson install -C $builddir --destdir $root --no-rebuild --tags $tags"
"$meson" install -C "$builddir" --destdir "$root" --no-rebuild --tags "$tags" --quiet

pcs=$(find "$root" -name calped.pc)
[[ $(wc -l <<<"$pcs") == 1 && -n $pcs ]] || { say "expected one installed calped.pc, found: ${pcs:-none}"; exit 1; }
say "installed $(find "$root" -type f | wc -l) files; ${pcs#"$root"}:"
sed 's/^/    /' "$pcs"

# A sysroot holds the package's dependencies as well: Eigen (calped.pc: Requires: eigen3)
# comes from the machine, linked into the root where its own .pc file points.
for dir in $(pkg-config --cflags-only-I eigen3); do
	dir=${dir#-I}
	mkdir -p "$root$(dirname "$dir")"
	[[ -e $root$dir ]] || ln -s "$dir" "$root$dir"
done

export PKG_CONFIG_PATH=$(dirname "$pcs") PKG_CONFIG_SYSROOT_DIR=$root
got=$(pkg-config --modversion calped)
[[ $got == "$version" ]] || { say "pkg-config --modversion calped: $got, expected $version"; exit 1; }
# Eigen is public (calibration.h includes it): Requires, not only Requires.private, which
# pkgconf would also read for --cflags but pkg-config and other tools do not.
pkg-config --print-requires calped | grep -q '^eigen3' ||
	{ say "calped.pc does not list eigen3 in Requires (the public headers include Eigen)"; exit 1; }
flags=$(pkg-config --cflags --libs calped)
say "pkg-config --cflags --libs calped: $flags"
# Every path the flags name must be inside the installed root: not the source or build tree.
for f in $flags; do
	case $f in
	-I* | -L*)
		p=${f:2}
		[[ $p == "$root"/* ]] || { say "$f is outside the installed root"; exit 1; }
		;;
	esac
done
[[ " $flags " == *" -lcalped "* ]] || { say "no -lcalped in the flags"; exit 1; }

cd "$tmp"
say "${cxx[*]} consumer.cpp -o consumer \$(pkg-config --cflags --libs calped)"
"${cxx[@]}" "$srcdir/consumer.cpp" -o consumer $flags
if [[ $default_library != shared ]]; then
	# The static library's own dependencies (Libs.private, Requires.private) must be complete.
	static_flags=$(pkg-config --static --cflags --libs calped)
	say "and with pkg-config --static: $static_flags"
	"${cxx[@]}" "$srcdir/consumer.cpp" -o consumer-static $static_flags
fi

libdir=$(dirname "$(find "$root" -name 'libcalped.*' | head -n 1)")
out=$(LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} ./consumer "$tmp/no-such-model.cpmodel")
echo "$out" | sed 's/^/    /'
expect() {
	grep -qx -- "$1" <<<"$out" || { say "the consumer's output has no line matching '$1'"; exit 1; }
}
expect "calped $version"
expect "cannot open $tmp/no-such-model.cpmodel"
expect "model refused (ModelTruncated): ModelTruncated: .*"
say "ok"
