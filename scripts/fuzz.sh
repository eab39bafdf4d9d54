#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# Builds the libFuzzer targets (tests/fuzz, build-fuzz/: clang-14, ASan + UBSan) and runs
# each one after the other on a copy of its seed corpus; fails on any crash, hang, leak,
# out-of-memory or sanitizer report. docs/testing.md explains the targets.
#   scripts/fuzz.sh [SECONDS_PER_TARGET | --runs N] [--max-time S] [--junit FILE] [TARGET...]
#     SECONDS_PER_TARGET  run each target this long (default 60)
#     --runs N            run each target for N executions instead (capped by --max-time S)
#     --junit FILE        also write one junit <testcase> per target (CI counts them)
#     TARGET...           only these (default: every fuzz_* binary built)
# Work folders: build-fuzz/fuzz-work/TARGET/{corpus,artifacts,log.txt}. The corpus grows
# from run to run; anything found is saved in artifacts/ (crash-*, leak-*, timeout-*,
# oom-*) and, once fixed, belongs in tests/fuzz/regressions/TARGET/ (replayed by meson test).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds=60
runs=
max_time=
junit=
targets=()
while (($# > 0)); do
	case $1 in
	--runs) runs=$2; shift 2 ;;
	--max-time) max_time=$2; shift 2 ;;
	--junit) junit=$2; shift 2 ;;
	-h|--help) sed -n '3,13p' "$0"; exit 0 ;;
	[0-9]*) seconds=$1; shift ;;
	-*) echo "fuzz: unknown option $1" >&2; exit 2 ;;
	*) targets+=("$1"); shift ;;
	esac
done

bash scripts/install-deps.sh clang-14 libclang-rt-14-dev llvm-14

builddir=build-fuzz
options=(-Dfuzzing=true -Db_sanitize=address,undefined -Db_lundef=false -Dtests=false
	-Dbuildtype=debugoptimized)
if [[ ! -f $builddir/meson-private/coredata.dat ]]; then
	CXX=clang++-14 meson setup "$builddir" "${options[@]}"
fi
ninja -C "$builddir" -j "${CALPED_JOBS:-2}" fuzz

if ((${#targets[@]} == 0)); then
	for exe in "$builddir"/tests/fuzz/fuzz_*; do
		[[ -f $exe && -x $exe ]] && targets+=("${exe##*/fuzz_}")
	done
fi

# Reports abort so libFuzzer stops on them; leaks are checked after every input that grew.
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:symbolize=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-14/bin/llvm-symbolizer}

limit=(-max_total_time="$seconds")
if [[ -n $runs ]]; then
	limit=(-runs="$runs")
	[[ -n $max_time ]] && limit+=(-max_total_time="$max_time")
fi

# Inputs up to 1 MiB, so superlinear parsing shows; targets whose inputs are small by
# nature get less, so the fuzzer does not spend its time growing inputs nothing reads.
max_len_for() {
	case $1 in
	probe_output) echo 4096 ;;  # ffprobe's "WxH": a few bytes; the cap on its output is 255
	aravis|libcamera) echo 1024 ;; # a camera's answers: a few dozen bytes are read
	detect) echo 65536 ;;       # 8 bytes of layout, then at most 96 x 128 x 3 pixel bytes
	*) echo 1048576 ;;
	esac
}

failed=()
rows=()
cases=()
for t in "${targets[@]}"; do
	exe=$builddir/tests/fuzz/fuzz_$t
	work=$builddir/fuzz-work/$t
	mkdir -p "$work/corpus" "$work/artifacts"
	# The copy libFuzzer adds to: the seeds and the regression inputs, never the sources.
	# Regressions over 64 KiB (the MB-sized inputs that bound the parsers' time) stay out:
	# libFuzzer would start mutating at their size (about 20 inputs a second for the
	# calibration parsers instead of thousands); `meson test` replays them in every build,
	# and the fuzzer still grows its own inputs up to -max_len.
	cp -n tests/fuzz/corpus/"$t"/* "$work/corpus/" 2>/dev/null || true
	if [[ -d tests/fuzz/regressions/$t ]]; then
		find tests/fuzz/regressions/"$t" -maxdepth 1 -type f -size -65537c \
			-exec cp -n {} "$work/corpus/" \;
	fi
	# The .mat reader's seeds are the toolbox's models, read from ../shared (not in the tree).
	if [[ $t == mat ]]; then
		cp -n "${CALPED_SHARED_DIR:-../shared}"/models/dollar-toolbox/*.mat "$work/corpus/" 2>/dev/null || true
	fi
	dict=()
	[[ -f tests/fuzz/dict/$t.dict ]] && dict=(-dict=tests/fuzz/dict/$t.dict)
	echo "=== fuzz $t: ${limit[*]}"
	start=$SECONDS
	began=$EPOCHREALTIME
	# -timeout: one input running 10 s is a hang (CALPED_FUZZ_TIMEOUT: another bound; the
	# long run's, at the lowest priority beside other work, is longer); -rss_limit_mb: 2 GB
	# is an out-of-memory.
	# -max_len: inputs up to 1 MB, so that superlinear parsing shows (the default is 4 KB),
	# unless the target's inputs are small by nature (max_len_for).
	# The log is passed through as libFuzzer writes it; the moment its "INITED" line comes
	# (the corpus loaded and run once) is noted, so that the rate after loading can be told
	# from the whole run's, which short runs on large seeds make meaningless.
	set +e
	"$exe" "${limit[@]}" "${dict[@]}" -timeout="${CALPED_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 -max_len="$(max_len_for "$t")" \
		-print_final_stats=1 -artifact_prefix="$work/artifacts/" "$work/corpus" 2>&1 |
		while IFS= read -r line || [[ -n $line ]]; do
			printf '%s\n' "$line"
			[[ $line == '#'*[[:space:]]INITED[[:space:]]* ]] && printf '%s %s\n' "$EPOCHREALTIME" "$line" >"$work/inited.txt"
		done >"$work/log.txt"
	statuses=("${PIPESTATUS[@]}")
	set -e
	rc=${statuses[0]}
	ended=$EPOCHREALTIME
	elapsed=$((SECONDS - start))
	stat() { sed -n "s/^stat::$1: *//p" "$work/log.txt" | tail -1; }
	execs=$(stat number_of_executed_units)
	rate=$(stat average_exec_per_sec)
	# Seconds to load the corpus, and executions per second from then to the end.
	load=? loaded_rate=?
	if [[ -s $work/inited.txt && -n $execs ]]; then
		read -r at initline <"$work/inited.txt"
		at_execs=$(sed -n 's/^#\([0-9]*\).*/\1/p' <<<"$initline")
		read -r load loaded_rate < <(awk -v b="$began" -v a="$at" -v e="$ended" -v n0="$at_execs" -v n="$execs" \
			'BEGIN { r = (e - a > 0.5) ? (n - n0) / (e - a) : 0; printf "%.1f %d\n", a - b, r }')
	fi
	# The machine's load average as the run ended: these rates depend on it.
	echo "$execs $rate $loaded_rate $load $(cut -d' ' -f1-3 /proc/loadavg)" >"$work/rates.txt"
	# The last progress line holds coverage: "#N DONE cov: C ft: F corp: U/S ...".
	progress=$(grep -E '^#[0-9]+' "$work/log.txt" | tail -1 || true)
	cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$progress")
	ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$progress")
	corp=$(sed -n 's/.* corp: \([0-9]*\).*/\1/p' <<<"$progress")
	result=ok
	if ((rc != 0)) || grep -qE '^(==[0-9]+==ERROR|SUMMARY: (Address|UndefinedBehavior|Leak)Sanitizer)' "$work/log.txt"; then
		result="FAILED (exit $rc)"
		failed+=("$t")
		grep -E 'ERROR|SUMMARY|runtime error|Test unit written' "$work/log.txt" | head -8 >&2 || true
	fi
	rows+=("$(printf '%-13s %12s %8s %9s %6ss %6s %7s %6s %5ss  %s' "$t" "${execs:-?}" "${rate:-?}" \
		"$loaded_rate" "$load" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$elapsed" "$result")")
	if [[ $result == ok ]]; then
		cases+=("<testcase classname=\"fuzz\" name=\"$t\" time=\"$elapsed\"/>")
	else
		cases+=("<testcase classname=\"fuzz\" name=\"$t\" time=\"$elapsed\"><failure message=\"libFuzzer exit $rc, see $work/log.txt\"/></testcase>")
	fi
done

echo
# exec/s: the whole run's (libFuzzer's figure); loaded/s: after the corpus was loaded
# (load: the seconds that took), the target's own speed.
printf '%-13s %12s %8s %9s %7s %6s %7s %6s %6s  %s\n' target executions exec/s loaded/s load cov ft corpus time result
printf '%s\n' "${rows[@]}"

if [[ -n $junit ]]; then
	mkdir -p "$(dirname "$junit")"
	{
		printf '<?xml version="1.0" encoding="UTF-8"?>\n'
		printf '<testsuites><testsuite name="fuzz" tests="%d" failures="%d">\n' \
			"${#targets[@]}" "${#failed[@]}"
		printf '%s\n' "${cases[@]}"
		printf '</testsuite></testsuites>\n'
	} >"$junit"
fi

if ((${#failed[@]} > 0)); then
	echo "fuzz: FAILED: ${failed[*]} (inputs in $builddir/fuzz-work/TARGET/artifacts/)" >&2
	exit 1
fi
echo "fuzz: ${#targets[@]} targets, no reports"
