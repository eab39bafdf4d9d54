#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Copies Dollár's trained detectors from ../shared into models/ and converts the INRIA one
# to calped's blob, models/AcfInriaDetector.cpm. Needs a built tree (scripts/build.sh).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

shared=${CALPED_SHARED_DIR:-../shared}
src="$shared/models/dollar-toolbox"
builddir=${CALPED_BUILD_DIR:-build}
convert="$builddir/tools/convert/calped-convert"

shopt -s nullglob
mats=("$src"/*.mat)
if ((${#mats[@]} == 0)); then
	echo "setup-models: no *.mat models in $src" >&2
	echo "setup-models: get Dollár's trained detectors from Piotr's Computer Vision Matlab Toolbox" >&2
	echo "setup-models: (GitHub pdollar/toolbox, folder detector/models/: AcfInriaDetector.mat ...)" >&2
	echo "setup-models: and put them in $src, or set CALPED_SHARED_DIR" >&2
	exit 1
fi

mkdir -p models
for m in "${mats[@]}"; do
	dst="models/$(basename "$m")"
	if [[ ! -f "$dst" ]] || ! cmp -s "$m" "$dst"; then
		echo "setup-models: copying $m -> $dst"
		install -m 0644 "$m" "$dst"
	fi
done

if [[ ! -f models/AcfInriaDetector.mat ]]; then
	echo "setup-models: $src has no AcfInriaDetector.mat" >&2
	exit 1
fi
if [[ ! -x "$convert" ]]; then
	echo "setup-models: $convert is not built (run: bash scripts/build.sh $builddir; it needs libmatio-dev)" >&2
	exit 1
fi

out=models/AcfInriaDetector.cpm
if [[ -f "$out" && "$out" -nt models/AcfInriaDetector.mat && "$out" -nt "$convert" ]]; then
	echo "setup-models: $out is up to date"
else
	echo "setup-models: $convert models/AcfInriaDetector.mat $out"
	rm -f "$out"
	"$convert" models/AcfInriaDetector.mat "$out.tmp"
	mv "$out.tmp" "$out"
fi
echo "setup-models: ready: $out ($(wc -c <"$out") bytes)"
