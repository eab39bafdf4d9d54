#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Where the calibrated mode's instructions go, kernel by kernel, beside the generic mode's
# (issue 4's time target): callgrind over PETS frames FIRST .. FIRST+2 (plus bench_detect's
# warm-up call on the first), resize 2, both resized inside the pyramid, the calibrated mode
# with placed levels. Prints M instructions per frame for each kernel in each mode, their
# ratio and each kernel's share of its mode's total. A kernel whose ratio is above the
# total's gains the calibrated mode more when it gets faster; below, the generic mode.
#   bash bench/kernel-shares.sh [FIRST]      (default 400; needs a build with bench/)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

first=${1:-400}
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
bash scripts/fetch-pets.sh "$((first + 2))" >/dev/null
tmp=$(mktemp -d)
trap '[[ -n "${CALPED_KEEP:-}" ]] || rm -rf "$tmp"' EXIT

profile() { # name, bench arguments... -> $tmp/name.tsv: kernel <tab> instructions
	local name=$1
	shift
	valgrind --tool=callgrind --callgrind-out-file="$tmp/$name.out" \
		--toggle-collect='calped::Detector::detect*' "$bench" --model "$model" \
		--frames data/pets/frames --first "$first" --count 3 --repeat 1 --resize 2 \
		--resize-in-pyramid --calib "$calib" "$@" >/dev/null 2>&1
	# Self cost per function, grouped: kernels by name without their build suffix (the
	# resampler's column pass counts as resampling), everything else as "other".
	callgrind_annotate --threshold=100 "$tmp/$name.out" 2>/dev/null | awk '
		/PROGRAM TOTALS/ { gsub(",", "", $1); print "total\t" $1; next }
		/^ *[0-9,]+ +\(/ && /:/ {
			n = $1; gsub(",", "", n)
			f = $0; sub(/^[^:]*:/, "", f); gsub(/\(anonymous namespace\)::/, "", f); sub(/\(.*/, "", f)
			k = "other"
			if (f ~ /calped::kernels::/) {
				k = f; sub(/.*::/, "", k); sub(/_(ref|opt|avx2|neon)$/, "", k)
				if (k == "columnPass" || k == "planPairs") k = "resamplePlanes"
				if (k == "") k = "other"
				if (k ~ /^scan/) k = "trees" # the grid scan (generic) or the list (calibrated)
			}
			sum[k] += n
		}
		END { for (k in sum) print k "\t" sum[k] }' >"$tmp/$name.tsv"
}

profile calibrated --calibrated --calibrated-pyramid
profile generic

echo "PETS frames $first-$((first + 2)), resize 2 inside the pyramid, M instructions per frame"
echo "(4 detect calls: bench_detect's warm-up and 3 frames):"
echo
echo "| kernel | calibrated, placed | share | generic | share | ratio |"
echo "|---|---:|---:|---:|---:|---:|"
awk -F'\t' '
	FNR == 1 { file++ }
	file == 1 { c[$1] = $2; keys[$1] = 1 }
	file == 2 { g[$1] = $2; keys[$1] = 1 }
	END {
		ct = c["total"]; gt = g["total"]
		for (k in keys) if (k != "total") order[n++] = k
		# largest generic cost first
		for (i = 0; i < n; i++) for (j = i + 1; j < n; j++)
			if (g[order[j]] > g[order[i]]) { t = order[i]; order[i] = order[j]; order[j] = t }
		for (i = 0; i < n; i++) {
			k = order[i]
			if (c[k] + g[k] < 0.005 * (ct + gt)) { oc += c[k]; og += g[k]; continue }
			printf "| %s | %.1f | %.1f%% | %.1f | %.1f%% | %s |\n", k, c[k] / 4e6, 100 * c[k] / ct,
				g[k] / 4e6, 100 * g[k] / gt, (g[k] > 0 ? sprintf("%.2f", c[k] / g[k]) : "-")
		}
		if (oc + og >= 2e5) printf "| (the rest) | %.1f | %.1f%% | %.1f | %.1f%% | %.2f |\n", oc / 4e6, 100 * oc / ct,
			og / 4e6, 100 * og / gt, (og > 0 ? oc / og : 0)
		printf "| **total** | **%.1f** | | **%.1f** | | **%.2f** |\n", ct / 4e6, gt / 4e6, ct / gt
	}' "$tmp/calibrated.tsv" "$tmp/generic.tsv"
