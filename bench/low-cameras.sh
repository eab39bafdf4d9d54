#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Calibrated vs generic mode for cameras close to the ground (issue 4, item 6): synthetic
# pinhole cameras 1.0, 1.5 and 2.0 m above the ground, level or pitched down 5 degrees
# (focal length 500 pixels, centre of a 768x576 image), written as plain projection
# matrices and run over PETS frames at resize 1 (the pixels only set the cost; nobody
# stands where these cameras look). Prints windows and ms per frame for the generic mode,
# the calibrated mode and the calibrated mode with placed pyramid levels.
#   bash bench/low-cameras.sh [FRAMES]        (default 20; needs a build with bench/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

frames=${1:-20}
bench=${CALPED_BUILD_DIR:-build}/bench/bench_detect
model=models/AcfInriaDetector.cpm
if [[ ! -x "$bench" || ! -f "$model" ]]; then
	echo "low-cameras: needs $bench and $model (bash scripts/build.sh build -Dtests=true;" \
		"bash scripts/setup-models.sh)" >&2
	exit 1
fi
bash scripts/fetch-pets.sh "$frames" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# P = K [R | t] with R = tilt(pitch) * level (camera z along world y, image y down),
# t = -R * (0, 0, height), in metres. A positive pitch of tilt() turns the optical axis
# up, (0, cos, sin) in the world: pitched down by `deg` is tilt(-deg), which puts the
# horizon above the image centre.
writeP() {
	awk -v h="$1" -v deg="$2" 'BEGIN {
		f = 500; cx = 384; cy = 288; p = -deg * atan2(0, -1) / 180; c = cos(p); s = sin(p)
		print "# synthetic camera " h " m above the ground, pitched down " deg " degrees"
		print "unit: m"
		printf "%.6f %.6f %.6f %.6f\n", f, cx * c, cx * s, -cx * s * h
		printf "%.6f %.6f %.6f %.6f\n", 0, f * s + cy * c, -f * c + cy * s, f * c * h - cy * s * h
		printf "%.6f %.6f %.6f %.6f\n", 0, c, s, -s * h
	}' >"$3"
}

run() { # label, bench arguments... -> "label: W windows/frame, M ms/frame"
	local label=$1
	shift
	local out
	out=$("$bench" --model "$model" --frames data/pets/frames --count "$frames" --repeat 1 "$@" 2>&1)
	local windows ms
	windows=$(sed -n 's/.* \([0-9]*\) windows\/frame.*/\1/p' <<<"$out" | head -n 1)
	ms=$(awk '/^  total/ {print $2}' <<<"$out")
	printf '  %-28s %8s windows/frame %8s ms/frame\n' "$label" "$windows" "$ms"
}

for height in 1.0 1.5 2.0; do
	for pitch in 0 5; do
		calib=$tmp/camera_${height}_${pitch}.txt
		writeP "$height" "$pitch" "$calib"
		echo "camera $height m, pitch $pitch deg:"
		run generic --resize 1
		run calibrated --resize 1 --calib "$calib" --levels toolbox
		run "calibrated, placed levels" --resize 1 --calib "$calib"
	done
done
