#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# DetectorConfig::threads on this machine (issue 18): calped-detect with the default
# calibrated configuration (--calib PETS view 1; the resize it chooses, placed levels) over
# the PETS frames with --threads 1, 2, 3 and 4, one run after the other in one go. Each
# run's CSV must be byte-identical to one thread's (cmp). Prints, per thread count, the
# run's frames per second (wall clock, decoding included: with --threads above 1 the next
# PNG decodes while the current frame is detected), the detector's own mean ms per frame,
# the summed user and system CPU seconds, and the speed-ups over one thread. Then the
# detector alone: build/bench/bench_detect with the same flags over the same frames decoded
# into memory first (no PNG decoding beside it), one detector per thread count and every
# frame detected by each in turn (--alternate-threads), so that the machine's drift in
# speed falls on all alike; its detections must agree too. Builds nothing; wall-clock
# numbers are only meaningful on an otherwise idle machine.
#   bash bench/threads.sh [FRAMES] [THREADS...]   (default: all 795 frames; 1 2 3 4)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

frames=${1:-795}
shift || true
counts=("$@")
[[ ${#counts[@]} -gt 0 ]] || counts=(1 2 3 4)
detect=${CALPED_BUILD_DIR:-build}/tools/detect/calped-detect
model=models/AcfInriaDetector.cpm
calib=../shared/data/pets2009-s2l1/View_001.xml
for f in "$detect" "$model" data/pets/frames/000001.png; do
	if [[ ! -e $f ]]; then
		echo "threads: needs $f (bash scripts/build.sh build; bash scripts/setup-models.sh;" \
			"bash scripts/fetch-pets.sh)" >&2
		exit 1
	fi
done
if [[ ! -f $calib ]]; then
	echo "threads: skipped: $calib is absent (the PETS calibration from ../shared)" >&2
	exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "calped-detect --calib View_001.xml, PETS frames 1-$frames, $(nproc) online cores," \
	"load $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| threads | frames/s (wall) | speed-up | detector ms/frame | detector speed-up | CPU s (user+sys) | CSV |"
echo "|---:|---:|---:|---:|---:|---:|---|"
base_fps= base_ms= status=0
for n in "${counts[@]}"; do
	/usr/bin/time -f '%U %S' -o "$tmp/time-$n" "$detect" --model "$model" --calib "$calib" \
		--threads "$n" --max-frames "$frames" --csv "$tmp/$n.csv" data/pets/frames 2>"$tmp/log-$n"
	summary=$(grep 'summary:' "$tmp/log-$n")
	wall=$(sed -n 's/.*wall_s=\([0-9.]*\).*/\1/p' <<<"$summary")
	ms=$(sed -n 's/.*ms_mean=\([0-9.]*\).*/\1/p' <<<"$summary")
	count=$(sed -n 's/.*frames=\([0-9]*\).*/\1/p' <<<"$summary")
	cpu=$(awk '{ printf "%.1f", $1 + $2 }' "$tmp/time-$n")
	fps=$(awk -v c="$count" -v w="$wall" 'BEGIN { printf "%.2f", c / w }')
	[[ -n $base_fps ]] || { base_fps=$fps; base_ms=$ms; first=$n; }
	if cmp -s "$tmp/$first.csv" "$tmp/$n.csv"; then
		same="identical to $first"
	else
		same="DIFFERS from $first"
		status=1
	fi
	awk -v n="$n" -v fps="$fps" -v bf="$base_fps" -v ms="$ms" -v bm="$base_ms" -v cpu="$cpu" -v same="$same" \
		'BEGIN { printf "| %s | %.2f | %.2fx | %.2f | %.2fx | %s | %s |\n", n, fps, fps / bf, ms, bm / ms, cpu, same }'
done

bench=${CALPED_BUILD_DIR:-build}/bench/bench_detect
if [[ -x $bench ]]; then
	echo
	echo "The detector alone (bench_detect --alternate-threads, frames 1-$frames in memory):"
	echo
	list=$(IFS=,; echo "${counts[*]}")
	"$bench" --model "$model" --calib "$calib" --frames data/pets/frames --count "$frames" \
		--alternate-threads "$list" | sed -n '/^side by side/,$p' || status=1
fi
exit $status
