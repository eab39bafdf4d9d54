#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Configures (or reconfigures) a Meson build folder and builds it.
#   scripts/build.sh [BUILDDIR] [meson options...]     e.g. scripts/build.sh build -Dbuildtype=release
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

builddir=${1:-build}
shift || true
jobs=${CALPED_JOBS:-2}

if [[ -f "$builddir/meson-private/coredata.dat" ]]; then
	echo "build: reconfiguring $builddir $*"
	meson setup --reconfigure "$builddir" "$@"
else
	echo "build: configuring $builddir $*"
	meson setup "$builddir" "$@"
fi
echo "build: ninja -C $builddir -j $jobs"
ninja -C "$builddir" -j "$jobs"
