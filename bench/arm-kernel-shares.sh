#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Where the instructions go on ARM, kernel by kernel: bench/kernel-shares.sh's table for a
# cross build under qemu-user, whose TCG plugin (toolchains/qemu-insn-profile.c) counts the
# instructions of every translated block; blocks are mapped to functions with the cross
# nm. PETS frames FIRST .. FIRST+2 at resize 2 inside the pyramid, one thread, calibrated
# (placed levels) and generic: the frames are detected once and then twice (bench_detect
# --repeat), and the difference is three detect() calls, so set-up is left out.
#   bash bench/arm-kernel-shares.sh [aarch64|armhf] [FIRST]   (default aarch64 400; needs
#   build-TARGET from scripts/cross-test.sh TARGET)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

target=aarch64
first=400
for a in "$@"; do
	case $a in
	aarch64|armhf) target=$a ;;
	*) first=$a ;;
	esac
done
case $target in
aarch64) qemu=qemu-aarch64 runtime=/usr/aarch64-linux-gnu nm=aarch64-linux-gnu-nm ;;
armhf) qemu=qemu-arm runtime=/usr/arm-linux-gnueabihf nm=arm-linux-gnueabihf-nm ;;
esac
bench=build-$target/bench/bench_detect
model=models/AcfInriaDetector.cpm
calib=../shared/data/pets2009-s2l1/View_001.xml
if [[ ! -x $bench || ! -f $model ]]; then
	echo "arm-kernel-shares: needs $bench and $model (bash scripts/cross-test.sh $target;" \
		"bash scripts/setup-models.sh)" >&2
	exit 1
fi
if [[ ! -f $calib ]]; then
	echo "arm-kernel-shares: skipped: $calib is absent (the PETS calibration from ../shared)" >&2
	exit 0
fi
bash scripts/fetch-pets.sh "$((first + 2))" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cc -O2 -shared -fPIC -o "$tmp/profile.so" toolchains/qemu-insn-profile.c

# The program's functions: start, end and name, sorted by start.
"$nm" -n -S -C --defined-only "$bench" |
	awk 'NF >= 4 && ($3 == "T" || $3 == "t") {
		name = $4; for (i = 5; i <= NF; i++) name = name " " $i
		printf "%s %s %s\n", $1, $2, name }' >"$tmp/symbols"

profile() { # name repeat bench-arguments... -> $tmp/name.tsv: kernel <tab> instructions
	local name=$1 repeat=$2
	shift 2
	"$qemu" -plugin "$tmp/profile.so,out=$tmp/$name.blocks" -L "$runtime" \
		-E "LD_LIBRARY_PATH=$runtime/lib" "$bench" --model "$model" --frames data/pets/frames \
		--first "$first" --count 3 --repeat "$repeat" --resize 2 --threads 1 "$@" >/dev/null 2>&1
	# PIE programs run at a base address qemu chooses: the block addresses less the base
	# fall inside the program's functions; blocks elsewhere (the C library) count as
	# "other". Grouping as bench/kernel-shares.sh does.
	awk -v syms="$tmp/symbols" '
		function hex(s,   i, v) {
			v = 0; s = tolower(s)
			for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
			return v
		}
		BEGIN {
			while ((getline line < syms) > 0) {
				split(line, f, " "); n++
				start[n] = hex(f[1]); end[n] = start[n] + hex(f[2])
				sub(/^[^ ]+ [^ ]+ /, "", line); name[n] = line
			}
		}
		{
			a = hex($1); c = $2
			lo = 1; hi = n; k = 0
			off = a - base
			while (lo <= hi) { mid = int((lo + hi) / 2); if (start[mid] <= off) { k = mid; lo = mid + 1 } else hi = mid - 1 }
			fn = (k > 0 && off < end[k]) ? name[k] : ""
			kern = "other"
			if (fn ~ /calped::kernels::/) {
				g = fn; gsub(/\(anonymous namespace\)::/, "", g); sub(/\(.*/, "", g)
				while (g ~ /<[^<>]*>/) gsub(/<[^<>]*>/, "", g)
				sub(/.*::/, "", g); sub(/_(ref|opt|avx2|neon)$/, "", g)
				if (g ~ /^(columnPass|planPairs|planBlock|planWindow|planChunk|rowPass|rowPassChunk|windowRows|pairBlockRows|resamplePlane)$/) g = "resamplePlanes"
				if (g == "sumEightPixels" || g == "hist6") g = "gradHist4"
				if (g ~ /^scan/) g = "trees"
				if (g != "") kern = g
			}
			sum[kern] += c; total += c
		}
		END { for (k in sum) print k "\t" sum[k]; print "total\t" total }' base="$base" "$tmp/$name.blocks" >"$tmp/$name.tsv"
}

# qemu-user loads a PIE program at 0x5500000000 on 64-bit guests, 0x40000000 on 32-bit ones.
if [[ $target == aarch64 ]]; then base=$((0x5500000000)); else base=$((0x40000000)); fi

profile cal1 1 --calib "$calib"
profile cal2 2 --calib "$calib"
profile gen1 1 --method generic
profile gen2 2 --method generic

perFrame() { # a.tsv b.tsv -> kernel <tab> (b - a) / 3
	awk -F'\t' 'FNR == NR { a[$1] = $2; next } { print $1 "\t" ($2 - a[$1]) / 3 }' "$1" "$2"
}
perFrame "$tmp/cal1.tsv" "$tmp/cal2.tsv" >"$tmp/cal.pf"
perFrame "$tmp/gen1.tsv" "$tmp/gen2.tsv" >"$tmp/gen.pf"

echo "$target (qemu-user), PETS frames $first-$((first + 2)), resize 2 inside the pyramid, M instructions per frame"
echo
echo "| kernel | calibrated, placed | share | generic | share |"
echo "|---|---:|---:|---:|---:|"
awk -F'\t' '
	FNR == 1 { file++ }
	file == 1 { c[$1] = $2; keys[$1] = 1 }
	file == 2 { g[$1] = $2; keys[$1] = 1 }
	END {
		ct = c["total"]; gt = g["total"]
		for (k in keys) if (k != "total") order[n++] = k
		for (i = 0; i < n; i++) for (j = i + 1; j < n; j++)
			if (c[order[j]] > c[order[i]]) { t = order[i]; order[i] = order[j]; order[j] = t }
		for (i = 0; i < n; i++) {
			k = order[i]
			if (c[k] + g[k] < 0.005 * (ct + gt)) { oc += c[k]; og += g[k]; continue }
			printf "| %s | %.1f | %.1f%% | %.1f | %.1f%% |\n", k, c[k] / 1e6, 100 * c[k] / ct, g[k] / 1e6, 100 * g[k] / gt
		}
		if (oc + og > 0) printf "| (the rest) | %.1f | %.1f%% | %.1f | %.1f%% |\n", oc / 1e6, 100 * oc / ct, og / 1e6, 100 * og / gt
		printf "| **total** | **%.1f** | | **%.1f** | |\n", ct / 1e6, gt / 1e6
	}' "$tmp/cal.pf" "$tmp/gen.pf"
