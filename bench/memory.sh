#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# The detector's own memory (issue 18): RSS that create() and the frames add, for each
# configuration, frame size and thread count, measured by build/bench/soak_detector over
# the PETS frames (loaded into memory first; the table gives RSS above them). Prints a
# markdown table for docs/benchmarks.md's RAM budget. Builds nothing.
#   bash bench/memory.sh [FRAMES]   (distinct frames looped to 3x as many; default 40)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

frames=${1:-40}
soak=${CALPED_BUILD_DIR:-build}/bench/soak_detector
model=models/AcfInriaDetector.cpm
calib=../shared/data/pets2009-s2l1/View_001.xml
for f in "$soak" "$model" data/pets/frames/000001.png; do
	if [[ ! -e $f ]]; then
		echo "memory: needs $f (bash scripts/build.sh build; bash scripts/setup-models.sh;" \
			"bash scripts/fetch-pets.sh)" >&2
		exit 1
	fi
done
if [[ ! -f $calib ]]; then
	echo "memory: skipped: $calib is absent (the PETS calibration from ../shared)" >&2
	exit 0
fi

# method | frame the detector sees | soak_detector flags
configs=(
	"calibrated (default)|768x576, resize 2 in the pyramid|--pyramid --resize 2"
	"calibrated (default)|768x576, resize 1|--pyramid --resize 1"
	"calibrated, toolbox levels|1536x1152 (frame resized 2x)|--resize 2"
	"generic|768x576, resize 2 in the pyramid|--generic --pyramid --resize 2"
	"generic|1536x1152 (frame resized 2x)|--generic --resize 2"
)
echo "soak_detector, PETS frames 1-$frames looped to $((3 * frames)) frames, $(nproc) online cores"
echo
echo "| method | frames | threads | after create() MiB | after the frames MiB | allocations per frame |"
echo "|---|---|---:|---:|---:|---:|"
status=0
for config in "${configs[@]}"; do
	IFS='|' read -r method frame flags <<<"$config"
	for threads in 1 2 4; do
		# shellcheck disable=SC2086 # flags are words
		out=$("$soak" --model "$model" --frames data/pets/frames --calib "$calib" --count "$frames" \
			--total $((3 * frames)) --warmup "$frames" --every "$frames" $flags --threads "$threads" 2>&1) || status=1
		loaded=$(sed -n 's/.*frames loaded \([0-9.]*\) MiB.*/\1/p' <<<"$out")
		created=$(sed -n 's/.*detector created \([0-9.]*\) MiB.*/\1/p' <<<"$out")
		end=$(sed -n 's/^RSS MiB .* end \([0-9.]*\) .*/\1/p' <<<"$out")
		allocs=$(sed -n 's/^allocations .*after (\([0-9.]*\) per frame).*/\1/p' <<<"$out")
		awk -v m="$method" -v f="$frame" -v t="$threads" -v l="$loaded" -v c="$created" -v e="$end" -v a="$allocs" \
			'BEGIN { printf "| %s | %s | %s | +%.1f | +%.1f | %s |\n", m, f, t, c - l, e - l, a }'
	done
done
exit $status
