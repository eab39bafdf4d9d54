#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# The benchmark table of docs/benchmarks.md (issue 18 item 5): for the generic and the
# calibrated method (both at resize 2 inside the pyramid, the calibrated one with its
# defaults: placed levels, the PETS calibration), per frame:
#   - ms on this machine: bench_detect's median total over PETS frames FIRST .. FIRST+N-1,
#     for 1, 2 and 4 threads when the detector takes --threads (probed in calped-detect
#     --help), else for 1 thread only;
#   - instructions on x86: callgrind over frames FIRST .. FIRST+2 with the collection on
#     inside Detector::detect only, divided by the 4 calls (bench_detect's warm-up call
#     repeats the first frame), as bench/kernel-shares.sh counts them;
#   - instructions on aarch64 and armhf: the qemu-user plugin of scripts/cross-insns.sh,
#     over frames FIRST, FIRST+1 run once and REPEAT times: the difference divided by the
#     extra detections (start-up, model loading and PNG decoding cancel out); only for a
#     cross build that has bench_detect (build-aarch64, build-armhf: scripts/cross-test.sh
#     or `ninja -C build-TARGET bench/bench_detect`), "-" otherwise;
#   - an estimate for a Cortex-A72 at 1.5 GHz: the aarch64 count / (IPC * 1.5e9), with the
#     IPC assumed (CALPED_A72_IPC, default 1.0; not measured on a board).
#   bash bench/bench-table.sh [--frames N] [--first F]     (default 20 frames from 400)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

frames=20
first=400
while (($# > 0)); do
	case $1 in
	--frames) frames=$2; shift 2 ;;
	--first) first=$2; shift 2 ;;
	*) echo "usage: bash bench/bench-table.sh [--frames N] [--first F]" >&2; exit 2 ;;
	esac
done
build=${CALPED_BUILD_DIR:-build}
bench=$build/bench/bench_detect
detect=$build/tools/detect/calped-detect
model=models/AcfInriaDetector.cpm
calib=../shared/data/pets2009-s2l1/View_001.xml
ipc=${CALPED_A72_IPC:-1.0}
if [[ ! -x "$bench" || ! -x "$detect" || ! -f "$model" ]]; then
	echo "bench-table: needs $bench, $detect and $model (bash scripts/build.sh build" \
		"-Dtests=true; bash scripts/setup-models.sh)" >&2
	exit 1
fi
if [[ ! -f "$calib" ]]; then
	echo "bench-table: skipped: $calib is absent (the PETS calibration from ../shared)" >&2
	exit 0
fi
bash scripts/fetch-pets.sh "$((first + frames))" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

threads=(1)
if "$detect" --help 2>&1 | grep -q -- '--threads'; then
	threads=(1 2 4)
fi

# The two configurations: name and bench_detect flags.
configs=(generic calibrated)
flagsOf() {
	case $1 in
	generic) echo "--method generic --resize 2" ;;
	calibrated) echo "--calib $calib --resize 2" ;;
	esac
}

# Median ms per frame of bench_detect's total.
msPerFrame() { # config threads
	local t=()
	[[ $2 != 1 || ${#threads[@]} -gt 1 ]] && t=(--threads "$2")
	# shellcheck disable=SC2046
	"$bench" --model "$model" --frames data/pets/frames --first "$first" --count "$frames" \
		$(flagsOf "$1") "${t[@]}" 2>&1 | awk '$1 == "total" { print $2 }'
}

# Instructions are counted on one thread: more threads add the split rectangles' margins
# and the pool's spinning, and valgrind and qemu-user run the threads one at a time anyway.
oneThread=()
((${#threads[@]} > 1)) && oneThread=(--threads 1)

# M instructions per detect() call on x86 (callgrind).
x86Insns() { # config
	# shellcheck disable=SC2046
	valgrind --tool=callgrind --callgrind-out-file="$tmp/$1.cg" \
		--toggle-collect='calped::Detector::detect*' "$bench" --model "$model" \
		--frames data/pets/frames --first "$first" --count 3 --repeat 1 $(flagsOf "$1") "${oneThread[@]}" \
		>/dev/null 2>&1
	callgrind_annotate "$tmp/$1.cg" 2>/dev/null |
		awk '/PROGRAM TOTALS/ { gsub(",", "", $1); printf "%.1f", $1 / 4 / 1e6 }'
}

# M instructions per detect() call under qemu-user, "-" without a cross build.
plugin=$tmp/insn-count.so
armInsns() { # target config
	local dir=build-$1 qemu runtime
	case $1 in
	aarch64) qemu=qemu-aarch64 runtime=/usr/aarch64-linux-gnu ;;
	armhf) qemu=qemu-arm runtime=/usr/arm-linux-gnueabihf ;;
	esac
	if [[ ! -x "$dir/bench/bench_detect" ]] || ! command -v "$qemu" >/dev/null; then
		echo "-"
		return
	fi
	[[ -f "$plugin" ]] || cc -O2 -shared -fPIC -o "$plugin" toolchains/qemu-insn-count.c
	count() { # repeat
		# shellcheck disable=SC2046
		"$qemu" -d plugin -plugin "$plugin" -L "$runtime" -E "LD_LIBRARY_PATH=$runtime/lib" \
			"$dir/bench/bench_detect" --model "$model" --frames data/pets/frames \
			--first "$first" --count 2 --repeat "$1" $(flagsOf "$2") "${oneThread[@]}" 2>&1 >/dev/null |
			awk '/^insns / { print $2 }'
	}
	local one more
	one=$(count 1 "$2")
	more=$(count 4 "$2")
	awk -v a="$one" -v b="$more" 'BEGIN { printf "%.1f", (b - a) / 6 / 1e6 }'
}

declare -A ms x86 a64 a32
for c in "${configs[@]}"; do
	for t in "${threads[@]}"; do
		ms[$c,$t]=$(msPerFrame "$c" "$t")
	done
	x86[$c]=$(x86Insns "$c")
	a64[$c]=$(armInsns aarch64 "$c")
	a32[$c]=$(armInsns armhf "$c")
done

echo "calped $(git rev-parse --short HEAD), PETS 768x576 at resize 2 inside the pyramid;" \
	"ms: median of frames $first-$((first + frames - 1)) on $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo
head="| method |"
rule="|---|"
for t in 1 2 4; do
	head+=" ms, $t thread$([[ $t == 1 ]] || echo s) |"
	rule+="---:|"
done
head+=" M insns x86 (callgrind) | M insns aarch64 (qemu) | M insns armhf (qemu) | Cortex-A72 1.5 GHz, IPC $ipc (est. ms) |"
rule+="---:|---:|---:|---:|"
echo "$head"
echo "$rule"
for c in "${configs[@]}"; do
	row="| $c |"
	for t in 1 2 4; do
		row+=" ${ms[$c,$t]:--} |"
	done
	est=-
	[[ ${a64[$c]} != - ]] && est=$(awk -v m="${a64[$c]}" -v i="$ipc" 'BEGIN { printf "%.0f", m * 1e6 / (i * 1.5e9) * 1e3 }')
	row+=" ${x86[$c]} | ${a64[$c]} | ${a32[$c]} | $est |"
	echo "$row"
done
