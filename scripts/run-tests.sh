#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-2-Clause
# THE TEST COMMAND. Installs dependencies and the first 50 PETS frames (data/pets/frames),
# then builds and runs the whole test suite twice:
#   build/       release
#   build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer, meson's 'sanitize' setup
#                (any report fails the test; docs/testing.md)
# then builds the core and the threads suite with ThreadSanitizer (build-tsan/, the 'tsan'
# setup) and runs its synthetic cases, then runs every libFuzzer target for $CALPED_FUZZ_SECONDS (default 10) seconds
# (scripts/fuzz.sh, build-fuzz/, clang-14), then cross-builds the suite for each of
# $CALPED_CROSS (default aarch64; empty: none) and runs it under qemu-user
# (scripts/cross-test.sh, build-aarch64/).
# The last line is "N passed, N failed, N skipped", counting GoogleTest cases of all runs,
# the Python binding's pytest cases (merged into Meson's junit log, tests/python) and one
# case per fuzz target.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

start=$SECONDS
jobs=${CALPED_JOBS:-2}
export CALPED_JOBS=$jobs

bash scripts/install-deps.sh
# The parity tests compare with Dollár's toolbox on PETS frames 1-50 and skip without them.
# A failed download is not a test failure, but it must not pass unnoticed.
if ! bash scripts/fetch-pets.sh 50; then
	echo "run-tests: WARNING: no PETS frames; the tests that need them will be skipped" >&2
fi

failed_steps=()
junits=()
# Each step's wall time, printed at the end beside the total: what to look at when the run
# nears CI's budget (docs/testing.md).
step_times=()
step_start=$SECONDS
step_done() {
	step_times+=("$1 $((SECONDS - step_start)) s")
	step_start=$SECONDS
}
step_done set-up

# run_suite NAME BUILDDIR [meson options...]: build, then meson test; failures are
# recorded, not fatal, so the second tree still runs and the summary is always printed.
run_suite() {
	local name=$1 builddir=$2
	shift 2
	echo
	echo "=== $name: $builddir"
	if ! bash scripts/build.sh "$builddir" "$@"; then
		failed_steps+=("$name build")
		return
	fi
	# SUITE_TEST_ARGS: extra meson test arguments, e.g. --setup=sanitize; a test setup
	# names Meson's log after it (testlog-sanitize.junit.xml).
	local test_args=(${SUITE_TEST_ARGS-})
	local setup=
	for a in "${test_args[@]}"; do
		[[ $a == --setup=* ]] && setup=-${a#--setup=}
	done
	local log="$builddir/meson-logs/testlog$setup.junit.xml"
	rm -f "$log"
	# gtest leaves NAME.xml beside each test; a stale one must not stand in for a crash.
	find "$builddir" -maxdepth 1 -name '*.xml' -delete
	if ! meson test -C "$builddir" --print-errorlogs --num-processes "$jobs" --no-rebuild \
		"${test_args[@]}"; then
		failed_steps+=("$name tests")
	fi
	if [[ -f "$log" ]]; then
		junits+=("$log")
	else
		failed_steps+=("$name: no junit log")
	fi
}

run_suite release build -Dbuildtype=release -Dtests=true
step_done release

# The 'sanitize' test setup (tests/meson.build) makes every ASan, LSan and UBSan report fatal.
SUITE_TEST_ARGS=--setup=sanitize run_suite sanitizers build-asan -Dbuildtype=debugoptimized \
	-Db_sanitize=address,undefined -Db_lundef=false -Dtests=true
step_done sanitizers

# ThreadSanitizer over the detector's threads (DetectorConfig::threads): only the core and
# the threads suite's binary are built, and only its small cases run (the pool, and every
# parallel section once); the 'tsan' setup makes any report fatal.
echo
echo "=== tsan: build-tsan"
tsan_log=build-tsan/meson-logs/testlog-tsan.junit.xml
if [[ -f build-tsan/meson-private/coredata.dat ]]; then
	tsan_setup=(meson setup --reconfigure build-tsan)
else
	tsan_setup=(meson setup build-tsan)
fi
if "${tsan_setup[@]}" -Dbuildtype=debugoptimized -Db_sanitize=thread -Db_lundef=false -Dtests=true &&
	ninja -C build-tsan -j "$jobs" tests/core/threads_tests; then
	rm -f "$tsan_log"
	if ! meson test -C build-tsan --setup=tsan --no-rebuild --print-errorlogs threads \
		--test-args=--gtest_filter='ThreadPool.*:Threads.EverySectionOnce'; then
		failed_steps+=("tsan tests")
	fi
	if [[ -f $tsan_log ]]; then
		junits+=("$tsan_log")
	else
		failed_steps+=("tsan: no junit log")
	fi
else
	failed_steps+=("tsan build")
fi
step_done tsan

# Every fuzz target briefly, on its seeds and what earlier runs found: one junit case each.
echo
echo "=== fuzz: build-fuzz"
fuzz_junit=build-fuzz/fuzz-junit.xml
rm -f "$fuzz_junit"
if ! bash scripts/fuzz.sh "${CALPED_FUZZ_SECONDS:-10}" --junit "$fuzz_junit"; then
	failed_steps+=("fuzz")
fi
if [[ -f $fuzz_junit ]]; then
	junits+=("$fuzz_junit")
else
	failed_steps+=("fuzz: no junit log")
fi
step_done fuzz

# ARM under emulation; the release tree's calped-convert prepares the model on the host.
for target in ${CALPED_CROSS-aarch64}; do
	echo
	echo "=== cross $target: build-$target"
	log=build-$target/meson-logs/testlog.junit.xml
	rm -f "$log"
	convert=
	if [[ -x build/tools/convert/calped-convert ]]; then
		convert=$PWD/build/tools/convert/calped-convert
	fi
	if ! CALPED_CONVERT=$convert bash scripts/cross-test.sh "$target"; then
		failed_steps+=("cross $target")
	fi
	if [[ -f "$log" ]]; then
		junits+=("$log")
	else
		failed_steps+=("cross $target: no junit log")
	fi
	step_done "cross-$target"
done

read -r passed failed skipped < <(bash scripts/count-junit.sh "${junits[@]}")

# A test executable can fail without a failing case (a leak report at exit, a crash
# before gtest wrote its XML): meson then fails the step, and it counts as one failure.
if ((${#failed_steps[@]} > 0)); then
	echo
	echo "failed steps: ${failed_steps[*]}"
	if ((failed < ${#failed_steps[@]})); then
		failed=${#failed_steps[@]}
	fi
fi

echo
echo "step times: $(IFS=,; echo "${step_times[*]}" | sed 's/,/, /g')"
echo "test time: $((SECONDS - start)) s (${#junits[@]} junit logs)"
rc=0
if ((failed > 0 || ${#failed_steps[@]} > 0)); then
	rc=1
elif ((passed == 0)); then
	echo "no test ran"
	rc=1
fi
if ((skipped > 0)); then
	echo "$passed passed, $failed failed, $skipped skipped"
else
	echo "$passed passed, $failed failed"
fi
exit $rc
