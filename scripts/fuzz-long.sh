#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# The long fuzz run (issue 19): each target (scripts/fuzz.sh, same build and checks) to a
# number of executions, then the fuzz table -- target, executions, exec/s (the whole run's
# and after the corpus was loaded), corpus size, findings -- written into docs/testing.md
# between its fuzz-table markers, with the date, the machine's core count, its load average
# as the target's run ended and the command, so the numbers say how they were made.
#   scripts/fuzz-long.sh [--runs N] [--max-time S] [TARGET...]
#     --runs N       executions per target (default 10000000, the issue's figure)
#     --max-time S   stop a target after S seconds even if N is not reached (default none);
#                    the table then shows the executions actually made
#     TARGET...      only these (default: every fuzz_* binary); rows of other targets in
#                    the table are kept as they were
# Findings are the files in build-fuzz/fuzz-work/TARGET/artifacts/ after the run: each one,
# once fixed, belongs in tests/fuzz/regressions/TARGET/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

runs=10000000
max_time=
targets=()
while (($# > 0)); do
	case $1 in
	--runs) runs=$2; shift 2 ;;
	--max-time) max_time=$2; shift 2 ;;
	-h|--help) sed -n '3,15p' "$0"; exit 0 ;;
	-*) echo "fuzz-long: unknown option $1" >&2; exit 2 ;;
	*) targets+=("$1"); shift ;;
	esac
done

# Hours at the lowest priority on a machine that may be busy: libFuzzer times an input by
# the wall clock, so a process kept off the CPU for 10 s would report a false hang. An
# input that runs 60 s is still one.
export CALPED_FUZZ_TIMEOUT=${CALPED_FUZZ_TIMEOUT:-60}
args=(--runs "$runs")
[[ -n $max_time ]] && args+=(--max-time "$max_time")
rc=0
bash scripts/fuzz.sh "${args[@]}" "${targets[@]}" || rc=$?

if ((${#targets[@]} == 0)); then
	for exe in build-fuzz/tests/fuzz/fuzz_*; do
		[[ -f $exe && -x $exe ]] && targets+=("${exe##*/fuzz_}")
	done
fi

doc=docs/testing.md
begin='<!-- fuzz-table-begin -->'
end='<!-- fuzz-table-end -->'
if ! grep -qF "$begin" "$doc" || ! grep -qF "$end" "$doc"; then
	echo "fuzz-long: $doc has no fuzz-table markers" >&2
	exit 1
fi
# The rows already in the table, by target, so that a partial run keeps the others.
declare -A row
while IFS= read -r line; do
	name=$(sed -n 's/^| `\([a-z_0-9]*\)` |.*/\1/p' <<<"$line")
	[[ -n $name ]] && row[$name]=$line
done < <(sed -n "/$begin/,/$end/p" "$doc")

when=$(date -u +%Y-%m-%d)
for t in "${targets[@]}"; do
	work=build-fuzz/fuzz-work/$t
	log=$work/log.txt
	execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
	rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
	# After the corpus was loaded (scripts/fuzz.sh notes when): the target's own speed.
	loaded=?
	load=$(cut -d' ' -f1-3 /proc/loadavg)
	if [[ -f $work/rates.txt ]]; then
		read -r _ _ loaded _ ended <"$work/rates.txt"
		[[ -n $ended ]] && load=$ended
	fi
	corpus=$(find "$work/corpus" -type f | wc -l)
	# Slow-unit reports are libFuzzer's note of an input over 10 s of wall clock, which load
	# alone can cause (a hang is a timeout-* file): counted apart, not as findings.
	findings=$(find "$work/artifacts" -type f ! -name 'slow-unit-*' | wc -l)
	slow=$(find "$work/artifacts" -type f -name 'slow-unit-*' | wc -l)
	slowNote=
	((slow == 0)) || slowNote="; $slow slow-unit reports in artifacts/"
	row[$t]="| \`$t\` | ${execs:-?} | ${rate:-?} | ${loaded:-?} | $corpus | $findings | $when, $(nproc) cores (load average $load as it ended), \`--runs $runs${max_time:+ --max-time $max_time}\`, timeout ${CALPED_FUZZ_TIMEOUT} s$slowNote |"
done

tmp=$(mktemp)
{
	sed -n "1,/$begin/p" "$doc"
	echo '| target | executions | exec/s | after loading | corpus | findings | run |'
	echo '|---|---|---|---|---|---|---|'
	for t in $(printf '%s\n' "${!row[@]}" | sort); do
		echo "${row[$t]}"
	done
	sed -n "/$end/,\$p" "$doc"
} >"$tmp"
mv "$tmp" "$doc"
echo "fuzz-long: table written to $doc"
exit "$rc"
