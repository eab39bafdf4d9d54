#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Where the calibrated mode's instructions go, kernel by kernel, beside the generic mode's
# (issue 4's time target): callgrind over PETS frames FIRST .. FIRST+2 (plus bench_detect's
# warm-up call on the first), resize 2, both resized inside the pyramid, the calibrated mode
# with placed levels. Prints M instructions per frame for each kernel in each mode, their
# ratio and each kernel's share of its mode's total. A kernel whose ratio is above the
# total's gains the calibrated mode more when it gets faster; below, the generic mode.
# With --reject-static the calibrated mode is calibrated-static (static-scene rejection
# and its gate of the sparse grid): its background needs 50 frames first, so it runs
# frames FIRST-50 .. FIRST+2 and FIRST-50 .. FIRST-1 and keeps the difference.
#   bash bench/kernel-shares.sh [FIRST] [--reject-static]   (default 400; needs a build
#   with bench/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

first=400
static=
for a in "$@"; do
	case $a in
	--reject-static) static=1 ;;
	*) first=$a ;;
	esac
done
bench=${CALPED_BUILD_DIR:-build}/bench/bench_detect
model=models/AcfInriaDetector.cpm
calib=../shared/data/pets2009-s2l1/View_001.xml
if [[ ! -x "$bench" || ! -f "$model" ]]; then
	echo "kernel-shares: needs $bench and $model (bash scripts/build.sh build -Dtests=true;" \
		"bash scripts/setup-models.sh)" >&2
	exit 1
fi
if [[ ! -f "$calib" ]]; then
	echo "kernel-shares: skipped: $calib is absent (the PETS calibration from ../shared)" >&2
	exit 0
fi
bash scripts/install-deps.sh >/dev/null
if [[ -n $static && $first -le 50 ]]; then
	echo "kernel-shares: with --reject-static FIRST must be above 50" >&2
	exit 1
fi
bash scripts/fetch-pets.sh "$((first + 2))" >/dev/null
tmp=$(mktemp -d)
trap '[[ -n "${CALPED_KEEP:-}" ]] || rm -rf "$tmp"' EXIT

profile() { # name, first frame, frames, bench arguments... -> $tmp/name.tsv: kernel <tab> instructions
	local name=$1 from=$2 count=$3
	shift 3
	valgrind --tool=callgrind --callgrind-out-file="$tmp/$name.out" \
		--toggle-collect='calped::Detector::detect*' "$bench" --model "$model" \
		--frames data/pets/frames --first "$from" --count "$count" --repeat 1 --resize 2 --threads 1 \
		--calib "$calib" "$@" >/dev/null 2>&1
	# Self cost per function, grouped by kernel (bench/kernel-name.awk).
	callgrind_annotate --threshold=100 "$tmp/$name.out" 2>/dev/null | awk -f bench/kernel-name.awk -f bench/callgrind-kernels.awk >"$tmp/$name.tsv"
}

# Per frame: (a - b) / frames, kernel by kernel (b may be absent: a / frames).
perFrame() { # out, frames, a.tsv [b.tsv]
	awk -F'\t' -v frames="$2" 'FNR == NR { a[$1] = $2; next } { b[$1] = $2 }
		END { for (k in a) print k "\t" (a[k] - b[k]) / frames }' "$3" "${4:-/dev/null}" >"$1"
}

# bench_detect detects its first frame once more before timing: 4 calls for 3 frames.
profile generic "$first" 3 --method generic
perFrame "$tmp/generic.pf" 4 "$tmp/generic.tsv"
if [[ -n $static ]]; then
	label="calibrated-static, placed"
	profile all "$((first - 50))" 53 --reject-static &
	profile warmup "$((first - 50))" 50 --reject-static &
	wait
	perFrame "$tmp/calibrated.pf" 3 "$tmp/all.tsv" "$tmp/warmup.tsv"
else
	label="calibrated, placed"
	profile calibrated "$first" 3
	perFrame "$tmp/calibrated.pf" 4 "$tmp/calibrated.tsv"
fi

echo "PETS frames $first-$((first + 2)), resize 2 inside the pyramid, M instructions per frame"
echo
awk -v label="$label" -f bench/kernel-table.awk "$tmp/calibrated.pf" "$tmp/generic.pf"
