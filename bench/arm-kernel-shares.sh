#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Where the instructions go on ARM, kernel by kernel: bench/kernel-shares.sh's table for a
# cross build under qemu-user, whose TCG plugin (toolchains/qemu-insn-profile.c) counts the
# instructions of every translated block; blocks are mapped to functions with the cross
# nm. PETS frames FIRST .. FIRST+2 at resize 2 inside the pyramid, one thread, calibrated
# (placed levels) and generic: the frames are detected once and then twice (bench_detect
# --repeat), and the difference is three detect() calls, so set-up is left out.
#   bash bench/arm-kernel-shares.sh [aarch64|armhf] [FIRST]   (default aarch64 400; needs
#   build-TARGET from scripts/cross-test.sh TARGET). Checked on aarch64 only: armhf's load
#   address below is qemu's documented default, not yet tried.
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
	awk 'NF >= 4 && $3 ~ /^[TtWw]$/ {
		name = $4; for (i = 5; i <= NF; i++) name = name " " $i
		printf "%s %s %s\n", $1, $2, name }' >"$tmp/symbols"

profile() { # name repeat bench-arguments... -> $tmp/name.tsv: kernel <tab> instructions
	local name=$1 repeat=$2
	shift 2
	"$qemu" -plugin "$tmp/profile.so,out=$tmp/$name.blocks" -L "$runtime" \
		-E "LD_LIBRARY_PATH=$runtime/lib" "$bench" --model "$model" --frames data/pets/frames \
		--first "$first" --count 3 --repeat "$repeat" --resize 2 --threads 1 "$@" >/dev/null 2>&1
	# Blocks to functions to kernels, grouped as bench/kernel-shares.sh does.
	awk -v syms="$tmp/symbols" -v base="$base" -f bench/kernel-name.awk -f bench/qemu-blocks-kernels.awk \
		"$tmp/$name.blocks" >"$tmp/$name.tsv"
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
awk -v label="calibrated, placed" -f bench/kernel-table.awk "$tmp/cal.pf" "$tmp/gen.pf"
