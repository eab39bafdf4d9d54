#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Benchmark of the generic detector on PETS 2009 S2L1 frames, one core: per-frame times at
# native size and at resize 2 beside Dollár's toolbox's medians, and callgrind instruction
# counts per frame (stable on a noisy machine). Usage: bash bench/run-bench.sh [FRAMES]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

frames=${1:-50}
bash scripts/install-deps.sh
bash scripts/build.sh build -Dbuildtype=release -Dtests=true >/dev/null
bash scripts/setup-models.sh >/dev/null
bash scripts/fetch-pets.sh "$frames" >/dev/null

model=models/AcfInriaDetector.cpm
bench=build/bench/bench_detect
# The toolbox's medians measured on this machine kind (issue #2; timing_*.csv in
# ../shared/reference/dollar-toolbox-pets/).
declare -A toolbox=([1]=41.8 [2]=162.6)

echo "calped $(git rev-parse --short HEAD), $(lscpu | sed -n 's/^Model name: *//p' | head -n 1), $(date -u +%F)"
for resize in 1 2; do
	echo
	echo "== resize $resize, $frames frames, median of 3 passes"
	taskset -c 0 "$bench" --model "$model" --frames data/pets/frames --count "$frames" \
		--resize "$resize" --resize-at frame --repeat 3 | tee /tmp/calped-bench.txt
	ours=$(awk '/^  total/ {print $2}' /tmp/calped-bench.txt)
	awk -v o="$ours" -v t="${toolbox[$resize]}" \
		'BEGIN {printf "toolbox median %.1f ms, calped median %.2f ms: %.2fx faster\n", t, o, t / o}'
	if command -v valgrind >/dev/null; then
		# Count only inside Detector::detect: the warm-up call and 2 timed frames.
		valgrind --tool=callgrind --callgrind-out-file=/tmp/calped-callgrind.out \
			--toggle-collect='calped::Detector::detect*' "$bench" --model "$model" \
			--frames data/pets/frames --count 2 --resize "$resize" --resize-at frame >/dev/null 2>&1
		ir=$(callgrind_annotate /tmp/calped-callgrind.out 2>/dev/null |
			awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
		awk -v ir="$ir" 'BEGIN {printf "callgrind: %.1f million instructions per frame\n", ir / 3 / 1e6}'
	fi
done
