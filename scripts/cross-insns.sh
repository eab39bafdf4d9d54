#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Instructions per PETS frame of the generic detector on an ARM target, counted under
# qemu-user by a TCG plugin (toolchains/qemu-insn-count.c): the emulated counterpart of the
# callgrind figure of bench/run-bench.sh. Needs a cross build with the tests
# (scripts/cross-test.sh TARGET) and PETS frames 1-2.
#   scripts/cross-insns.sh aarch64|armhf [RESIZE...]      (default resizes: 1 2)
# bench_detect runs frames 1-2 once and then REPEAT times; the difference between the two
# counts, divided by the extra frames, is what Detector::detect executes per frame: start-up,
# model loading and PNG decoding cancel out.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
	echo "usage: scripts/cross-insns.sh aarch64|armhf [RESIZE...]" >&2
	exit 2
}
(($# >= 1)) || usage
target=$1
shift
case "$target" in
aarch64) triplet=aarch64-linux-gnu qemu=qemu-aarch64 ;;
armhf) triplet=arm-linux-gnueabihf qemu=qemu-arm ;;
*) usage ;;
esac
resizes=("$@")
((${#resizes[@]} > 0)) || resizes=(1 2)

builddir=build-$target
bench=$builddir/bench/bench_detect
convert=$builddir/tools/convert/calped-convert
work=$builddir/insn-count
if [[ ! -x "$bench" || ! -x "$convert" ]]; then
	echo "cross-insns: no $bench or $convert; run scripts/cross-test.sh $target first" >&2
	exit 1
fi
ninja -C "$builddir" bench/bench_detect >/dev/null
bash scripts/fetch-pets.sh 2 >/dev/null

mkdir -p "$work"
plugin=$work/insn-count.so
if [[ ! -f "$plugin" || toolchains/qemu-insn-count.c -nt "$plugin" ]]; then
	echo "cross-insns: cc -shared -fPIC -o $plugin toolchains/qemu-insn-count.c"
	cc -O2 -Wall -Wextra -shared -fPIC -o "$plugin" toolchains/qemu-insn-count.c
fi
model=$work/inria.cpm
"$convert" ../shared/models/dollar-toolbox/AcfInriaDetector.mat "$model" >/dev/null

runtime=/usr/$triplet
frames=2
repeat=4
# count REPEAT: the guest instructions of one bench_detect run (-d plugin routes the plugin's
# output to qemu's log, which is stderr).
count() {
	"$qemu" -d plugin -plugin "$plugin" -L "$runtime" -E "LD_LIBRARY_PATH=$runtime/lib" \
		"$bench" --model "$model" --frames data/pets/frames --count "$frames" \
		--resize "$resize" --resize-at frame --repeat "$1" 2>&1 >/dev/null | awk '/^insns / {print $2}'
}

flags=$(meson introspect --buildoptions "$builddir" |
	python3 -c 'import json, sys; print(*next(o["value"] for o in json.load(sys.stdin) if o["name"] == "cpp_args"))')
echo "calped $(git rev-parse --short HEAD), $target, cpp_args: ${flags:-none}"
for resize in "${resizes[@]}"; do
	one=$(count 1)
	more=$(count "$repeat")
	awk -v a="$one" -v b="$more" -v n="$((frames * (repeat - 1)))" -v r="$resize" -v t="$target" \
		'BEGIN {printf "%s, resize %s: %.1f million instructions per frame (qemu plugin, PETS frames 1-2)\n", t, r, (b - a) / n / 1e6}'
done
